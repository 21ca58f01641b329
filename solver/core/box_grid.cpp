#include "core/box_grid.h"

#include <algorithm>
#include <cmath>

namespace ib {

BoxGrid::BoxGrid(const Eigen::MatrixX2d& lo, const Eigen::MatrixX2d& hi, double cellSize) : cell_(cellSize) {
  if (lo.rows() == 0) {
    origin_.setZero();
    cells_.resize(1);
    return;
  }
  origin_ = lo.colwise().minCoeff().transpose();
  const Eigen::Vector2d extent = hi.colwise().maxCoeff().transpose() - origin_;
  // Cap the cell count so a tiny cell size on a huge extent cannot exhaust memory.
  const double maxCells = 4.0 * static_cast<double>(lo.rows()) + 16.0;
  while ((extent.x() / cell_ + 1) * (extent.y() / cell_ + 1) > maxCells) cell_ *= 1.5;
  nx_ = static_cast<int>(extent.x() / cell_) + 1;
  ny_ = static_cast<int>(extent.y() / cell_) + 1;
  cells_.resize(static_cast<size_t>(nx_) * ny_);
  for (int i = 0; i < lo.rows(); ++i) {
    const int x0 = cellX(lo(i, 0)), x1 = cellX(hi(i, 0)), y0 = cellY(lo(i, 1)), y1 = cellY(hi(i, 1));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cells_[y * nx_ + x].push_back(i);
  }
}

int BoxGrid::cellX(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - origin_.x()) / cell_)), 0, nx_ - 1);
}
int BoxGrid::cellY(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - origin_.y()) / cell_)), 0, ny_ - 1);
}

const std::vector<int>& BoxGrid::itemsAt(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d q = p - origin_;
  if (q.x() < 0 || q.y() < 0 || q.x() > nx_ * cell_ || q.y() > ny_ * cell_) return empty_;
  return cells_[cellY(p.y()) * nx_ + cellX(p.x())];
}

}  // namespace ib
