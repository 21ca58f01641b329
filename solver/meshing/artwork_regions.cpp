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
};

struct Regions {
  std::vector<Region> list;
  std::vector<int> label;  // [y * width + x]: index into list, or -1
  double drawn = 0;        // px^2 with alpha >= 128
};

int colourDistance(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// The drawing's regions: 4-connected fully opaque pixels within `tolerance` of the first one found.
Regions segment(const RgbaImage& image, int tolerance) {
  const int w = image.width, h = image.height;
  Regions out;
  out.label.assign(static_cast<size_t>(w) * h, -1);
  const auto colourAt = [&](int x, int y) {
    const uint8_t* p = image.at(x, y);
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  std::vector<int> stack;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      out.drawn += image.at(x, y)[3] >= 128;
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
bool clearOfPaper(const RgbaImage& image, const Eigen::Vector2d& p, double radius) {
  const int r = static_cast<int>(std::ceil(radius));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy > radius * radius) continue;
      const int x = static_cast<int>(std::floor(p.x())) + dx, y = static_cast<int>(std::floor(p.y())) + dy;
      if (x < 0 || y < 0 || x >= image.width || y >= image.height || image.at(x, y)[3] < 128) return false;
    }
  return true;
}

}  // namespace

std::vector<std::vector<Eigen::Vector2d>> artworkRegionPins(const std::vector<RgbaImage>& drawings, int reference,
                                                            double clearance, const ArtworkRegionOptions& options) {
  const int keys = static_cast<int>(drawings.size());
  std::vector<std::vector<Eigen::Vector2d>> pins(static_cast<size_t>(keys));
  if (keys < 2) return pins;
  std::vector<Regions> regions;
  for (const RgbaImage& image : drawings) regions.push_back(segment(image, options.colourTolerance));
  const Regions& ref = regions[static_cast<size_t>(reference)];
  const double size = std::sqrt(ref.drawn), reach = 0.3 * size;
  const int width = drawings[static_cast<size_t>(reference)].width;
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
    if (ref.label[static_cast<size_t>(std::floor(c.y())) * width + static_cast<size_t>(std::floor(c.x()))] != static_cast<int>(r))
      continue;  // a ring or a crescent: its centroid is not on it
    std::vector<const Region*> match(static_cast<size_t>(keys), &a);
    bool found = true, moved = false;
    for (int k = 0; k < keys && found; ++k) {
      if (k == reference) continue;
      double best = std::numeric_limits<double>::infinity(), second = best;
      for (const Region& b : regions[static_cast<size_t>(k)].list) {
        const int colour = colourDistance(a.colour, b.colour);
        const double ratio = b.area / a.area, distance = (b.centroid - c).norm();
        if (colour > 2 * options.colourTolerance || ratio < 0.4 || ratio > 2.5 || distance > reach || b.touchesPaper) continue;
        const double cost = colour / (2.0 * options.colourTolerance) + std::abs(std::log(ratio)) + distance / reach;
        if (cost < best) second = best, best = cost, match[static_cast<size_t>(k)] = &b;
        else second = std::min(second, cost);
      }
      found = best < std::numeric_limits<double>::infinity() && second >= best + 0.3;
      const Region& b = *match[static_cast<size_t>(k)];
      moved = moved || (b.centroid - c).norm() > 0.5 || std::abs(b.area / a.area - 1) > 0.05;
    }
    if (!found || !moved) continue;
    // Its centroid in every key, kept when clear of the paper and of the centroids kept before.
    bool keep = true;
    for (int k = 0; k < keys && keep; ++k) {
      const Eigen::Vector2d& at = match[static_cast<size_t>(k)]->centroid;
      keep = clearOfPaper(drawings[static_cast<size_t>(k)], at, clearance);
      for (const Eigen::Vector2d& q : pins[static_cast<size_t>(k)]) keep = keep && (q - at).norm() >= clearance;
    }
    if (!keep) continue;
    for (int k = 0; k < keys; ++k) pins[static_cast<size_t>(k)].push_back(match[static_cast<size_t>(k)]->centroid);
  }
  return pins;
}

}  // namespace ib
