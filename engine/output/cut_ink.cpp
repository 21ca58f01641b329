#include "output/cut_ink.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ib::render {

namespace {

// Bilinear straight-alpha sample (colour weighted by alpha), out of the image transparent.
std::array<double, 4> sample(const RgbaImage& image, double x, double y) {
  std::array<double, 4> sum{0, 0, 0, 0};
  const int x0 = static_cast<int>(std::floor(x - 0.5)), y0 = static_cast<int>(std::floor(y - 0.5));
  const double fx = x - 0.5 - x0, fy = y - 0.5 - y0;
  double alpha = 0;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const int px = x0 + dx, py = y0 + dy;
      if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
      const double w = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
      const uint8_t* p = image.at(px, py);
      const double a = w * p[3] / 255.0;
      for (int c = 0; c < 3; ++c) sum[c] += a * p[c] / 255.0;
      alpha += a;
    }
  if (alpha > 0)
    for (int c = 0; c < 3; ++c) sum[c] /= alpha;
  sum[3] = alpha;
  return sum;
}

double luminance(const std::array<double, 4>& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

}  // namespace

OutlineInk outlineInk(const RgbaImage& drawing, const Eigen::Vector2d& at, const Eigen::Vector2d& inward, double contrast) {
  OutlineInk ink;
  if (drawing.width <= 0 || inward.norm() <= 0) return ink;
  const Eigen::Vector2d d = inward.normalized();
  constexpr double kStep = 0.5, kFrom = -4, kTo = 24;
  std::vector<std::array<double, 4>> samples;
  std::vector<double> depth;
  for (double t = kFrom; t <= kTo + 1e-9; t += kStep) {
    const Eigen::Vector2d p = at + t * d;
    samples.push_back(sample(drawing, p.x(), p.y()));
    depth.push_back(t);
  }
  size_t first = 0;
  while (first < samples.size() && samples[first][3] < 0.5) ++first;
  if (first == samples.size()) return ink;
  std::vector<double> fill;
  for (size_t i = first; i < samples.size(); ++i)
    if (depth[i] - depth[first] >= 8 && samples[i][3] >= 0.5) fill.push_back(luminance(samples[i]));
  if (fill.size() < 4) return ink;
  std::nth_element(fill.begin(), fill.begin() + fill.size() / 2, fill.end());
  const double fillLuminance = fill[fill.size() / 2];
  size_t end = first;
  double darkest = 1;
  while (end < samples.size() && samples[end][3] >= 0.5 && luminance(samples[end]) <= fillLuminance - contrast) {
    darkest = std::min(darkest, luminance(samples[end]));
    ++end;
  }
  const double width = (end - first) * kStep;
  if (width < 1 || end >= samples.size() || depth.back() - depth[end - 1] < 2) return ink;
  // The colour of the line's core: its samples within a quarter of the way from the darkest to the
  // fill (its edges blend into the fill and the paper).
  std::array<double, 4> sum{0, 0, 0, 0};
  int core = 0;
  for (size_t i = first; i < end; ++i)
    if (luminance(samples[i]) <= darkest + 0.25 * (fillLuminance - darkest)) {
      for (int c = 0; c < 4; ++c) sum[c] += samples[i][c];
      ++core;
    }
  ink.found = true;
  ink.width = width;
  for (int c = 0; c < 4; ++c) ink.colour[c] = static_cast<float>(sum[c] / core);
  return ink;
}

Eigen::Vector2d inwardNormal(const RgbaImage& drawing, const Eigen::Vector2d& at, double radius) {
  Eigen::Vector2d sum(0, 0);
  const auto alpha = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= drawing.width || y >= drawing.height) return 0.0;
    return drawing.at(x, y)[3] / 255.0;
  };
  const int r = static_cast<int>(std::ceil(radius));
  for (int y = static_cast<int>(at.y()) - r; y <= static_cast<int>(at.y()) + r; ++y)
    for (int x = static_cast<int>(at.x()) - r; x <= static_cast<int>(at.x()) + r; ++x) {
      if (std::hypot(x + 0.5 - at.x(), y + 0.5 - at.y()) > radius) continue;
      sum += Eigen::Vector2d(alpha(x + 1, y) - alpha(x - 1, y), alpha(x, y + 1) - alpha(x, y - 1));
    }
  return sum.norm() > 1e-9 ? Eigen::Vector2d(sum.normalized()) : Eigen::Vector2d(0, 0);
}

}  // namespace ib::render
