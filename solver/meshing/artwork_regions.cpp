#include "meshing/artwork_regions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace ib {

namespace {

constexpr int kOpaque = 250;  // alpha: a region's pixels are this opaque or more (edges' blends are left out)

struct Region {
  std::array<int, 3> colour{};  // straight RGB of its first pixel
  double area = 0;              // px^2
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  bool touchesPaper = false;                              // a 4-neighbour is paper (alpha under 128) or outside
  std::array<int, 4> box{};                               // its pixels' columns and rows: x0, y0, x1, y1 (inclusive)
};

struct Regions {
  std::vector<Region> list;
  int width = 0, height = 0;   // of the drawing, px
  std::vector<int> label;      // [y * width + x]: index into list, or -1
  std::vector<uint8_t> paper;  // [y * width + x]: 1 where alpha < 128
  double drawn = 0;            // px^2 with alpha >= 128
};

int colourDistance(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// The drawing's regions: 4-connected fully opaque pixels within `tolerance` of the first one found.
Regions segment(const RgbaImage& image, int tolerance) {
  const int w = image.width, h = image.height;
  Regions out;
  out.width = w;
  out.height = h;
  out.label.assign(static_cast<size_t>(w) * h, -1);
  out.paper.assign(static_cast<size_t>(w) * h, 0);
  const auto colourAt = [&](int x, int y) {
    const uint8_t* p = image.at(x, y);
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  std::vector<int> stack;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      out.drawn += image.at(x, y)[3] >= 128;
      out.paper[static_cast<size_t>(y) * w + x] = image.at(x, y)[3] < 128;
      if (image.at(x, y)[3] < kOpaque || out.label[static_cast<size_t>(y) * w + x] >= 0) continue;
      Region r;
      r.colour = colourAt(x, y);
      const int id = static_cast<int>(out.list.size());
      Eigen::Vector2d sum(0, 0);
      stack.assign(1, y * w + x);
      out.label[static_cast<size_t>(y) * w + x] = id;
      while (!stack.empty()) {
        const int at = stack.back();
        stack.pop_back();
        const int px = at % w, py = at / w;
        const Eigen::Vector2d c(px + 0.5, py + 0.5);
        r.box = r.area == 0 ? std::array<int, 4>{px, py, px, py}
                            : std::array<int, 4>{std::min(r.box[0], px), std::min(r.box[1], py), std::max(r.box[2], px),
                                                 std::max(r.box[3], py)};
        r.area += 1;
        sum += c;
        const int nx[4] = {px - 1, px + 1, px, px}, ny[4] = {py, py, py - 1, py + 1};
        for (int n = 0; n < 4; ++n) {
          if (nx[n] < 0 || ny[n] < 0 || nx[n] >= w || ny[n] >= h || image.at(nx[n], ny[n])[3] < 128) {
            r.touchesPaper = true;
            continue;
          }
          const size_t i = static_cast<size_t>(ny[n]) * w + nx[n];
          if (out.label[i] >= 0 || image.at(nx[n], ny[n])[3] < kOpaque || colourDistance(colourAt(nx[n], ny[n]), r.colour) > tolerance)
            continue;
          out.label[i] = id;
          stack.push_back(static_cast<int>(i));
        }
      }
      r.centroid = sum / r.area;
      out.list.push_back(r);
    }
  return out;
}

// Whether every pixel centre within `radius` of p is drawn (alpha >= 128).
bool clearOfPaper(const Regions& image, const Eigen::Vector2d& p, double radius) {
  const int r = static_cast<int>(std::ceil(radius));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy > radius * radius) continue;
      const int x = static_cast<int>(std::floor(p.x())) + dx, y = static_cast<int>(std::floor(p.y())) + dy;
      if (x < 0 || y < 0 || x >= image.width || y >= image.height || image.paper[static_cast<size_t>(y) * image.width + x]) return false;
    }
  return true;
}

// The reference's regions that every other key has once and that moved (ArtworkRegions):
// [region][key], the index of the region matched in each key.
std::vector<std::vector<int>> movedRegions(const std::vector<Regions>& regions, int reference,
                                           const ArtworkRegionOptions& options) {
  const int keys = static_cast<int>(regions.size());
  const Regions& ref = regions[static_cast<size_t>(reference)];
  const double size = std::sqrt(ref.drawn), reach = 0.3 * size;
  std::vector<std::vector<int>> out;
  // The fill: the colour of the largest region. Pieces of it that other detail cuts off (the body
  // between two stripes, a tail of the body's colour) change shape with everything around them.
  const Region* fill = nullptr;
  for (const Region& a : ref.list)
    if (!fill || a.area > fill->area) fill = &a;
  for (size_t r = 0; r < ref.list.size(); ++r) {
    const Region& a = ref.list[r];
    if (a.area < options.minArea || a.area > options.maxShare * ref.drawn || a.touchesPaper) continue;
    if (colourDistance(a.colour, fill->colour) <= 2 * options.colourTolerance) continue;
    const Eigen::Vector2d& c = a.centroid;
    if (ref.label[static_cast<size_t>(std::floor(c.y())) * ref.width + static_cast<size_t>(std::floor(c.x()))] != static_cast<int>(r))
      continue;  // a ring or a crescent: its centroid is not on it
    std::vector<int> match(static_cast<size_t>(keys), static_cast<int>(r));
    bool found = true, moved = false;
    for (int k = 0; k < keys && found; ++k) {
      if (k == reference) continue;
      double best = std::numeric_limits<double>::infinity(), second = best;
      const std::vector<Region>& list = regions[static_cast<size_t>(k)].list;
      for (size_t j = 0; j < list.size(); ++j) {
        const Region& b = list[j];
        const int colour = colourDistance(a.colour, b.colour);
        const double ratio = b.area / a.area, distance = (b.centroid - c).norm();
        if (colour > 2 * options.colourTolerance || ratio < 0.4 || ratio > 2.5 || distance > reach || b.touchesPaper) continue;
        const double cost = colour / (2.0 * options.colourTolerance) + std::abs(std::log(ratio)) + distance / reach;
        if (cost < best) second = best, best = cost, match[static_cast<size_t>(k)] = static_cast<int>(j);
        else second = std::min(second, cost);
      }
      found = best < std::numeric_limits<double>::infinity() && second >= best + 0.3;
      const Region& b = list[static_cast<size_t>(match[static_cast<size_t>(k)])];
      moved = moved || (b.centroid - c).norm() > 0.5 || std::abs(b.area / a.area - 1) > 0.05;
    }
    if (found && moved) out.push_back(std::move(match));
  }
  return out;
}

// One place where a region meets the outline: the loop points at the middle and the two ends of
// the stretch of outline it touches, the ends in the loop's walking order.
struct Contact {
  Eigen::Vector2d middle, first, last;
  double length = 0;  // of the stretch along the loop, px
};

// Where region `id` of `regions` comes within `reach` px of `loops`: its border pixels that near,
// grouped by where along the loops they are nearest (a gap of more than `reach` starts a new
// group). Empty when it touches no loop.
std::vector<Contact> outlineContacts(const Regions& regions, int id, const std::vector<Polyline>& loops, double reach) {
  const int w = regions.width, h = static_cast<int>(regions.label.size()) / std::max(1, regions.width);
  std::vector<std::vector<double>> along(loops.size());  // [loop]: arc lengths of the near border pixels
  std::vector<ArcLengthLoop> parametrized;
  for (const Polyline& loop : loops) parametrized.emplace_back(loop);
  const std::array<int, 4>& box = regions.list[static_cast<size_t>(id)].box;
  for (int y = box[1]; y <= box[3]; ++y)
    for (int x = box[0]; x <= box[2]; ++x) {
      if (regions.label[static_cast<size_t>(y) * w + x] != id) continue;
      const bool border = x == 0 || y == 0 || x + 1 == w || y + 1 == h || regions.label[static_cast<size_t>(y) * w + x - 1] != id ||
                          regions.label[static_cast<size_t>(y) * w + x + 1] != id ||
                          regions.label[static_cast<size_t>(y - 1) * w + x] != id || regions.label[static_cast<size_t>(y + 1) * w + x] != id;
      if (!border) continue;
      const Eigen::Vector2d p(x + 0.5, y + 0.5);
      size_t bestLoop = 0;
      LoopPoint best;
      for (size_t l = 0; l < loops.size(); ++l) {
        const LoopPoint q = nearestOnLoop(loops[l], p);
        if (q.distance < best.distance) best = q, bestLoop = l;
      }
      if (best.distance > reach) continue;
      along[bestLoop].push_back(parametrized[bestLoop].parameterOf(best));
    }
  std::vector<Contact> out;
  for (size_t l = 0; l < loops.size(); ++l) {
    std::vector<double>& s = along[l];
    if (s.empty()) continue;
    const ArcLengthLoop& loop = parametrized[l];
    std::sort(s.begin(), s.end());
    // Start at the widest gap (cyclic), so no group is split at the loop's start.
    size_t start = 0;
    double widest = s.front() + loop.length() - s.back();
    for (size_t i = 1; i < s.size(); ++i)
      if (s[i] - s[i - 1] > widest) widest = s[i] - s[i - 1], start = i;
    double first = s[start], last = first;
    for (size_t n = 1; n <= s.size(); ++n) {
      const size_t i = (start + n) % s.size();
      double next = s[i];
      if (next < last) next += loop.length();
      if (n == s.size() || next - last > reach) {
        out.push_back({loop.at(0.5 * (first + last)), loop.at(first), loop.at(last), last - first});
        first = next;
      }
      last = next;
    }
  }
  return out;
}

}  // namespace

struct ArtworkRegions::Impl {
  int reference = 0;
  ArtworkRegionOptions options;
  std::vector<Regions> regions;          // [key]
  std::vector<std::vector<int>> moved;  // [region][key]: movedRegions

  const Region& region(size_t r, int k) const {
    return regions[static_cast<size_t>(k)].list[static_cast<size_t>(moved[r][static_cast<size_t>(k)])];
  }
};

ArtworkRegions::ArtworkRegions(const std::vector<RgbaImage>& drawings, int reference, const ArtworkRegionOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->reference = reference;
  impl_->options = options;
  if (drawings.size() < 2) return;
  for (const RgbaImage& image : drawings) impl_->regions.push_back(segment(image, options.colourTolerance));
  impl_->moved = movedRegions(impl_->regions, reference, options);
}

ArtworkRegions::~ArtworkRegions() = default;
ArtworkRegions::ArtworkRegions(ArtworkRegions&&) noexcept = default;
ArtworkRegions& ArtworkRegions::operator=(ArtworkRegions&&) noexcept = default;

std::vector<std::vector<Eigen::Vector2d>> ArtworkRegions::pins(double clearance) const {
  const int keys = static_cast<int>(impl_->regions.size());
  std::vector<std::vector<Eigen::Vector2d>> pins(static_cast<size_t>(keys));
  for (size_t r = 0; r < impl_->moved.size(); ++r) {
    // Its centroid in every key, kept when clear of the paper and of the centroids kept before.
    bool keep = true;
    for (int k = 0; k < keys && keep; ++k) {
      const Eigen::Vector2d& at = impl_->region(r, k).centroid;
      keep = clearOfPaper(impl_->regions[static_cast<size_t>(k)], at, clearance);
      for (const Eigen::Vector2d& q : pins[static_cast<size_t>(k)]) keep = keep && (q - at).norm() >= clearance;
    }
    if (!keep) continue;
    for (int k = 0; k < keys; ++k) pins[static_cast<size_t>(k)].push_back(impl_->region(r, k).centroid);
  }
  return pins;
}

std::vector<std::vector<Eigen::Vector2d>> ArtworkRegions::contacts(const std::vector<std::vector<Outline>>& outlines) const {
  const int keys = static_cast<int>(impl_->regions.size()), reference = impl_->reference;
  const ArtworkRegionOptions& options = impl_->options;
  std::vector<std::vector<Eigen::Vector2d>> out;
  if (keys < 2 || outlines.size() != impl_->regions.size()) return out;
  std::vector<std::vector<Polyline>> loops(static_cast<size_t>(keys));  // [key]: outer loops and holes
  for (int k = 0; k < keys; ++k)
    for (const Outline& o : outlines[static_cast<size_t>(k)]) {
      loops[static_cast<size_t>(k)].push_back(o.outer);
      loops[static_cast<size_t>(k)].insert(loops[static_cast<size_t>(k)].end(), o.holes.begin(), o.holes.end());
    }
  for (size_t r = 0; r < impl_->moved.size(); ++r) {
    std::vector<std::vector<Contact>> found(static_cast<size_t>(keys));  // [key][contact]
    for (int k = 0; k < keys; ++k)
      found[static_cast<size_t>(k)] = outlineContacts(impl_->regions[static_cast<size_t>(k)], impl_->moved[r][static_cast<size_t>(k)],
                                                      loops[static_cast<size_t>(k)], options.contactReach);
    const std::vector<Contact>& refContacts = found[static_cast<size_t>(reference)];
    bool same = !refContacts.empty();
    for (int k = 0; k < keys; ++k) same = same && found[static_cast<size_t>(k)].size() == refContacts.size();
    if (!same) continue;
    // Each reference contact with the key's contact in the nearest direction from the region's
    // centroid, when that is the reference contact's nearest in turn and within 45 deg; then the
    // ends of the stretch each touches, first with first and last with last.
    const auto direction = [&](int k, const Contact& c) {
      const Eigen::Vector2d d = c.middle - impl_->region(r, k).centroid;
      return std::atan2(d.y(), d.x());
    };
    const auto turn = [](double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); };
    const auto nearest = [&](int k, double want) {
      const std::vector<Contact>& own = found[static_cast<size_t>(k)];
      size_t best = 0;
      for (size_t j = 1; j < own.size(); ++j)
        if (turn(direction(k, own[j]), want) < turn(direction(k, own[best]), want)) best = j;
      return best;
    };
    for (size_t c = 0; c < refContacts.size(); ++c) {
      const double want = direction(reference, refContacts[c]);
      std::vector<Eigen::Vector2d> first(static_cast<size_t>(keys)), last(static_cast<size_t>(keys)), middle(first);
      bool paired = true, long_ = true;
      for (int k = 0; k < keys && paired; ++k) {
        const Contact& own = found[static_cast<size_t>(k)][nearest(k, want)];
        paired = nearest(reference, direction(k, own)) == c && turn(direction(k, own), want) < M_PI / 4;
        first[static_cast<size_t>(k)] = own.first;
        last[static_cast<size_t>(k)] = own.last;
        middle[static_cast<size_t>(k)] = own.middle;
        long_ = long_ && own.length >= 2 * options.contactReach;
      }
      if (!paired) continue;
      if (!long_) {  // a line's end, or a stretch too short in some key to hold two knots
        out.push_back(std::move(middle));
        continue;
      }
      out.push_back(std::move(first));
      out.push_back(std::move(last));
    }
  }
  return out;
}

}  // namespace ib
