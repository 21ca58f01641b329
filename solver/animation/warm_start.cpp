#include "animation/warm_start.h"

#include <algorithm>

namespace ib {

void WarmStartPredictor::clear() { count_ = 0; }

void WarmStartPredictor::remember(const Eigen::VectorXd& w, const Eigen::MatrixX2d& x) {
  if (count_ > 0 && (x.rows() != x1_.rows() || w.size() != w1_.size())) count_ = 0;  // another problem
  std::swap(w0_, w1_);
  std::swap(x0_, x1_);
  w1_ = w;
  x1_ = x;
  count_ = std::min(count_ + 1, 2);
}

std::optional<Eigen::MatrixX2d> WarmStartPredictor::predict(const Eigen::VectorXd& w) const {
  if (count_ == 0 || w.size() != w1_.size()) return std::nullopt;
  if (count_ == 1) return x1_;
  const Eigen::VectorXd last = w1_ - w0_;
  const double length2 = last.squaredNorm();
  if (!(length2 > 0)) return x1_;
  const double t = std::clamp(last.dot(w - w1_) / length2, 0.0, 2.0);
  return x1_ + t * (x1_ - x0_);
}

}  // namespace ib
