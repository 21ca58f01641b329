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
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      mask.inside[static_cast<size_t>(y) * image.width + x] = image.at(x, y)[3] >= options.alphaThreshold;
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
  if (outlines.empty())
    throw InputError(label + ": empty drawing (no shape of at least " + std::to_string(options.minArea) +
                     " px^2 after masking)");
  std::sort(outlines.begin(), outlines.end(),
            [](const Outline& a, const Outline& b) { return loopArea(a.outer) > loopArea(b.outer); });
  return outlines;
}

}  // namespace ib
