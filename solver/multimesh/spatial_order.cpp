#include "multimesh/spatial_order.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace ib {

namespace {

// Distance along the Hilbert curve of order 16 of cell (x, y), each in [0, 2^16).
uint64_t hilbertIndex(uint32_t x, uint32_t y) {
  uint64_t d = 0;
  for (uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += static_cast<uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant so that the curve stays continuous
      if (rx == 1) {
        x = s - 1 - (x & (s - 1));
        y = s - 1 - (y & (s - 1));
      }
      std::swap(x, y);
    }
    x &= s - 1;
    y &= s - 1;
  }
  return d;
}

}  // namespace

std::vector<int> hilbertOrder(const std::vector<Eigen::Vector2d>& points) {
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  if (points.empty()) return order;
  Eigen::Vector2d lo = points[0], hi = points[0];
  for (const Eigen::Vector2d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
  const double scale = 65535.0 / extent;
  std::vector<uint64_t> key(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d cell = (points[i] - lo) * scale;
    key[i] = hilbertIndex(static_cast<uint32_t>(std::clamp(cell.x(), 0.0, 65535.0)),
                          static_cast<uint32_t>(std::clamp(cell.y(), 0.0, 65535.0)));
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  return order;
}

std::vector<int> triangleOrder(const std::vector<Triangle>& triangles) {
  std::vector<int> order(triangles.size());
  std::iota(order.begin(), order.end(), 0);
  const auto sorted = [](Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return sorted(triangles[a]) < sorted(triangles[b]); });
  return order;
}

}  // namespace ib
