#include "meshing/tracing.h"

#include "core/error.h"
#include "meshing/paper.h"

#include <potracelib.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace ib {

double loopArea(const Polyline& loop) {
  double twice = 0;
  for (size_t i = 0, n = loop.size(); i < n; ++i) {
    const Eigen::Vector2d& a = loop[i];
    const Eigen::Vector2d& b = loop[(i + 1) % n];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

ShapeMask shapeMask(const RgbaImage& image, const TracingOptions& options, const Polyline& holePoints,
                    const std::string& label) {
  ShapeMask mask;
  mask.width = image.width;
  mask.height = image.height;
  mask.inside.assign(static_cast<size_t>(image.width) * image.height, 0);
  if (tracedByColour(image, options)) {
    const PaperMap paper = findPaper(image, options, holePoints, label);
    for (size_t i = 0; i < mask.inside.size(); ++i) mask.inside[i] = !paper.paper[i];
    return mask;
  }
  if (!holePoints.empty())
    throw InputError(label + ": holes: the drawing has alpha, so its holes are its transparent pixels; remove "
                     "\"holes\", or set tracing.background to trace it by colour");
  mask.alpha.resize(mask.inside.size());
  mask.threshold = options.alphaThreshold;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const size_t i = static_cast<size_t>(y) * image.width + x;
      mask.alpha[i] = image.at(x, y)[3];
      mask.inside[i] = mask.alpha[i] >= options.alphaThreshold;
    }
  return mask;
}

namespace {

// potrace's bitmap: rows of 64-bit words, the leftmost pixel in the most significant bit.
struct Bitmap {
  std::vector<potrace_word> words;
  potrace_bitmap_t view{};

  explicit Bitmap(const ShapeMask& mask) {
    constexpr int kBits = 8 * sizeof(potrace_word);
    const int dy = (mask.width + kBits - 1) / kBits;
    words.assign(static_cast<size_t>(dy) * mask.height, 0);
    // Scanline y is image row y, so potrace's coordinates are the drawing's pixel coordinates.
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x)
        if (mask.at(x, y))
          words[static_cast<size_t>(y) * dy + x / kBits] |= potrace_word(1) << (kBits - 1 - x % kBits);
    view.w = mask.width;
    view.h = mask.height;
    view.dy = dy;
    view.map = words.data();
  }
};

Eigen::Vector2d point(const potrace_dpoint_t& p) { return {p.x, p.y}; }

// Appends the cubic Bezier p0..p3 without p0, in as many equal parameter steps as keep the
// polygon within `tolerance` of the curve: the chord error is at most |B''|max / (8 n^2), and
// |B''| <= 6 max(|p0 - 2 p1 + p2|, |p1 - 2 p2 + p3|).
void flattenCubic(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2,
                  const Eigen::Vector2d& p3, double tolerance, Polyline& out) {
  const double bend = std::max((p0 - 2 * p1 + p2).norm(), (p1 - 2 * p2 + p3).norm());
  const int steps = std::clamp(static_cast<int>(std::ceil(std::sqrt(6 * bend / (8 * tolerance)))), 1, 256);
  for (int k = 1; k <= steps; ++k) {
    const double t = double(k) / steps, u = 1 - t;
    out.push_back(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
  }
}

Polyline flatten(const potrace_curve_t& curve, double tolerance) {
  Polyline loop;
  Eigen::Vector2d current = point(curve.c[curve.n - 1][2]);  // a closed curve starts where it ends
  for (int i = 0; i < curve.n; ++i) {
    if (curve.tag[i] == POTRACE_CORNER) {
      loop.push_back(point(curve.c[i][1]));
      loop.push_back(point(curve.c[i][2]));
    } else {
      flattenCubic(current, point(curve.c[i][0]), point(curve.c[i][1]), point(curve.c[i][2]), tolerance, loop);
    }
    current = point(curve.c[i][2]);
  }
  // Drop consecutive duplicates (a corner's vertex can coincide with the next segment's start).
  Polyline clean;
  for (const auto& p : loop)
    if (clean.empty() || (p - clean.back()).norm() > 1e-9) clean.push_back(p);
  while (clean.size() > 1 && (clean.front() - clean.back()).norm() <= 1e-9) clean.pop_back();
  return clean;
}

Polyline oriented(Polyline loop, bool positive) {
  if ((loopArea(loop) > 0) != positive) std::reverse(loop.begin(), loop.end());
  return loop;
}

// potrace's tree: a '+' path's children are its holes; a hole's children are islands inside it,
// which are components of their own.
void collect(const potrace_path_t* outer, double tolerance, std::vector<Outline>& out) {
  for (const potrace_path_t* p = outer; p; p = p->sibling) {
    Outline o;
    o.outer = oriented(flatten(p->curve, tolerance), true);
    for (const potrace_path_t* hole = p->childlist; hole; hole = hole->sibling) {
      o.holes.push_back(oriented(flatten(hole->curve, tolerance), false));
      collect(hole->childlist, tolerance, out);
    }
    if (o.outer.size() >= 3) out.push_back(std::move(o));
  }
}

// The mask's alpha minus its threshold at p (drawing px), clamped at the image's border: >= 0
// inside the shape. `soft`: bilinear between pixel centres (i + 0.5, j + 0.5), where an
// antialiased edge lies between them; else the alpha of the pixel p lies in, whose hard edge is the
// pixel's (a bilinear level would round a hard corner off: a 20 px square hole lost 8 px²).
double level(const ShapeMask& mask, const Eigen::Vector2d& p, bool soft) {
  if (!soft) {
    const int x = std::clamp(static_cast<int>(std::floor(p.x())), 0, mask.width - 1);
    const int y = std::clamp(static_cast<int>(std::floor(p.y())), 0, mask.height - 1);
    return double(mask.alpha[static_cast<size_t>(y) * mask.width + x]) - mask.threshold;
  }
  const double fx = std::clamp(p.x() - 0.5, 0.0, mask.width - 1.0), fy = std::clamp(p.y() - 0.5, 0.0, mask.height - 1.0);
  const int x0 = std::min(static_cast<int>(fx), mask.width - 1), y0 = std::min(static_cast<int>(fy), mask.height - 1);
  const int x1 = std::min(x0 + 1, mask.width - 1), y1 = std::min(y0 + 1, mask.height - 1);
  const double tx = fx - x0, ty = fy - y0;
  const auto a = [&](int x, int y) { return double(mask.alpha[static_cast<size_t>(y) * mask.width + x]); };
  return (1 - ty) * ((1 - tx) * a(x0, y0) + tx * a(x1, y0)) + ty * ((1 - tx) * a(x0, y1) + tx * a(x1, y1)) - mask.threshold;
}

// Whether a pixel within 1 px of p (drawing px) is partly transparent: there the edge lies between
// pixel centres where the drawing's antialiasing put it; elsewhere it is a pixel boundary.
bool antialiasedNear(const ShapeMask& mask, const Eigen::Vector2d& p) {
  const int cx = static_cast<int>(std::floor(p.x())), cy = static_cast<int>(std::floor(p.y()));
  for (int y = std::max(0, cy - 1); y <= std::min(mask.height - 1, cy + 1); ++y)
    for (int x = std::max(0, cx - 1); x <= std::min(mask.width - 1, cx + 1); ++x) {
      const uint8_t a = mask.alpha[static_cast<size_t>(y) * mask.width + x];
      if (a > 0 && a < 255) return true;
    }
  return false;
}

// Moves every point of `loop` along the normal (dy, -dx) of its neighbours' chord d, which points
// away from the shape for an outer loop (positive area) and a hole (negative) alike, onto the
// drawing's edge: the nearest crossing of the alpha threshold from inside to outside within
// `reach` px. The moves are then averaged over `smoothing` px of outline either way (a point
// with no crossing counts as not moving), so that the pixel grid's bilinear ripples do not
// become bends of the outline.
void onAntialiasedEdge(Polyline& loop, const ShapeMask& mask, double reach, double smoothing) {
  const size_t n = loop.size();
  if (n < 3 || mask.alpha.empty()) return;
  constexpr double kStep = 0.0625;  // px between level samples along the normal
  const int steps = static_cast<int>(std::ceil(reach / kStep));
  std::vector<Eigen::Vector2d> normal(n, Eigen::Vector2d::Zero());
  std::vector<double> move(n, 0.0), along(n + 1, 0.0);  // along: arc length at each point, then the loop's
  for (size_t i = 0; i < n; ++i) {
    along[i + 1] = along[i] + (loop[(i + 1) % n] - loop[i]).norm();
    const Eigen::Vector2d d = loop[(i + 1) % n] - loop[(i + n - 1) % n];
    if (!(d.norm() > 1e-9)) continue;
    normal[i] = Eigen::Vector2d(d.y(), -d.x()).normalized();
    const bool soft = antialiasedNear(mask, loop[i]);
    double best = NAN;
    for (int k = -steps; k < steps; ++k) {  // crossings between t and t + step, nearest to 0 wins
      const double t = k * kStep;
      const double inside = level(mask, loop[i] + t * normal[i], soft), beyond = level(mask, loop[i] + (t + kStep) * normal[i], soft);
      if (!(inside >= 0 && beyond < 0)) continue;
      const double at = t + kStep * inside / (inside - beyond);
      if (std::isnan(best) || std::abs(at) < std::abs(best)) best = at;
    }
    if (!std::isnan(best)) move[i] = best;
  }
  const double length = along[n];
  const Polyline traced = loop;
  for (size_t i = 0; i < n; ++i) {  // a tent of half-width `smoothing` over arc length, both ways round the loop
    double sum = move[i], weight = 1;
    for (const int dir : {-1, 1})
      for (size_t k = 1; k < n; ++k) {
        const size_t j = (i + n + dir * static_cast<long>(k) % static_cast<long>(n)) % n;
        double gap = std::abs(along[j] - along[i]);
        gap = std::min(gap, length - gap);
        if (gap >= smoothing) break;
        sum += (1 - gap / smoothing) * move[j];
        weight += 1 - gap / smoothing;
      }
    loop[i] = traced[i] + (sum / weight) * normal[i];
  }
  // Moves along neighbouring normals can swap two points where the outline turns sharply (a tip
  // at the image's border): a segment that turned round gets its two ends back where they were
  // traced, and the segments next to it are looked at again, so the loop stays as simple as potrace
  // made it. Each point goes back at most once: O(n).
  std::vector<size_t> segments(n);  // segment i runs from point i to point i + 1
  for (size_t i = 0; i < n; ++i) segments[i] = n - 1 - i;
  while (!segments.empty()) {
    const size_t i = segments.back(), j = (i + 1) % n;
    segments.pop_back();
    if ((loop[j] - loop[i]).dot(traced[j] - traced[i]) > 0 || (loop[i] == traced[i] && loop[j] == traced[j])) continue;
    loop[i] = traced[i];
    loop[j] = traced[j];
    segments.push_back((i + n - 1) % n);
    segments.push_back(j);
  }
}

// px: how far a traced point may move onto the drawing's edge (a sharp tip that potrace rounded
// comes back out by up to that much), and over how much outline either way the moves are
// averaged: the bilinear level ripples with the pixel grid, and averaged over 1 px those ripples
// were corners to the corner detection of a 64 px sprite (tests/drawn/leg/leg64: a knee corner
// in one key only, a correspondence shifted by one corner, smallest angle after Comesh 8.5
// degrees; 24 with 2 px).
constexpr double kEdgeReach = 1.0;
constexpr double kEdgeSmoothing = 2.0;

}  // namespace

std::vector<Outline> traceOutlines(const ShapeMask& mask, const TracingOptions& options, const std::string& label) {
  if (!(options.tolerance > 0)) throw InputError(label + ": tracing tolerance must be > 0");
  Bitmap bitmap(mask);
  std::unique_ptr<potrace_param_t, void (*)(potrace_param_t*)> param(potrace_param_default(), potrace_param_free);
  if (!param) throw std::runtime_error("potrace: out of memory");
  param->turdsize = static_cast<int>(std::floor(options.minArea));
  param->opttolerance = options.tolerance;  // potrace's own curve-joining error, same bound
  std::unique_ptr<potrace_state_t, void (*)(potrace_state_t*)> state(potrace_trace(param.get(), &bitmap.view),
                                                                      potrace_state_free);
  if (!state || state->status != POTRACE_STATUS_OK) throw std::runtime_error("potrace failed on " + label);
  std::vector<Outline> outlines;
  collect(state->plist, options.tolerance, outlines);
  for (Outline& o : outlines) {
    onAntialiasedEdge(o.outer, mask, kEdgeReach, kEdgeSmoothing);
    for (Polyline& hole : o.holes) onAntialiasedEdge(hole, mask, kEdgeReach, kEdgeSmoothing);
  }
  if (outlines.empty())
    throw InputError(label + ": empty drawing (no shape of at least " + std::to_string(options.minArea) +
                     " px^2 after masking)");
  std::sort(outlines.begin(), outlines.end(),
            [](const Outline& a, const Outline& b) { return loopArea(a.outer) > loopArea(b.outer); });
  return outlines;
}

}  // namespace ib
