#include "anderson.h"

#include <Eigen/Dense>

namespace ib {

AndersonAcceleration::AndersonAcceleration(int depth) : depth_(depth < 0 ? 0 : depth) {}

void AndersonAcceleration::reset() {
  stored_ = 0;
  newest_ = -1;
  previousF_.resize(0);
  previousG_.resize(0);
}

void AndersonAcceleration::restart() {
  previousF_.resize(0);
  previousG_.resize(0);
}

Eigen::VectorXd AndersonAcceleration::next(const Eigen::VectorXd& x, const Eigen::VectorXd& gx) {
  if (depth_ == 0) return gx;
  const Eigen::VectorXd f = gx - x;
  if (dF_.rows() != x.size()) {
    dF_.resize(x.size(), depth_);
    dG_.resize(x.size(), depth_);
    gram_.resize(depth_, depth_);
    reset();
  }
  if (previousF_.size() == x.size()) {
    newest_ = (newest_ + 1) % depth_;
    dF_.col(newest_) = f - previousF_;
    dG_.col(newest_) = gx - previousG_;
    if (stored_ < depth_) ++stored_;
    for (int j = 0; j < stored_; ++j) gram_(newest_, j) = gram_(j, newest_) = dF_.col(j).dot(dF_.col(newest_));
  }
  previousF_ = f;
  previousG_ = gx;
  if (stored_ == 0) return gx;

  const auto F = dF_.leftCols(stored_);
  Eigen::MatrixXd normal = gram_.topLeftCorner(stored_, stored_);
  // Tikhonov regularization keeps nearly dependent histories from blowing up gamma.
  normal.diagonal().array() += 1e-10 * normal.trace() + 1e-300;
  const Eigen::VectorXd gamma = normal.ldlt().solve(F.transpose() * f);
  if (!gamma.allFinite()) {
    reset();
    return gx;
  }
  return gx - dG_.leftCols(stored_) * gamma;
}

}  // namespace ib
