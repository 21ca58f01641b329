// Uniform grid over axis-aligned boxes, for the point and nearest-segment queries of the
// non-overlap term: building is O(items + covered cells), a query visits nearby cells only.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdlib>
#include <vector>

namespace ib {

class BoxGrid {
 public:
  // lo, hi: per item box corners (k x 2 each). cellSize > 0, in the same units.
  BoxGrid(const Eigen::MatrixX2d& lo, const Eigen::MatrixX2d& hi, double cellSize);

  // Items whose box may contain p.
  const std::vector<int>& itemsAt(const Eigen::Vector2d& p) const;

  // Visits items in cells at Chebyshev ring distance `ring` around p's cell (ring 0 = p's cell)
  // and returns false once the ring lies wholly outside the grid.
  // Visits items in the cells at Chebyshev distance `ring` from p's cell (ring 0 = p's cell).
  // Returns false once the ring lies wholly outside the grid. Items in ring r + 1 are at least
  // r * cellSize() from p.
  template <class Visit>
  bool visitRing(const Eigen::Vector2d& p, int ring, Visit&& visit) const {
    if (ring > std::max(nx_, ny_)) return false;
    const int cx = cellX(p.x()), cy = cellY(p.y());
    for (int y = std::max(cy - ring, 0); y <= std::min(cy + ring, ny_ - 1); ++y)
      for (int x = std::max(cx - ring, 0); x <= std::min(cx + ring, nx_ - 1); ++x) {
        if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring) continue;
        for (int item : cells_[y * nx_ + x]) visit(item);
      }
    return true;
  }

  double cellSize() const { return cell_; }

 private:
  int cellX(double x) const;
  int cellY(double y) const;
  Eigen::Vector2d origin_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
  std::vector<int> empty_;
};

}  // namespace ib
