#include "anderson.h"

#include <Eigen/Dense>
#include <algorithm>
#include <omp.h>
#include <utility>

namespace ib {

AndersonAcceleration::AndersonAcceleration(int depth, int threads)
    : depth_(std::clamp(depth, 0, kMaxDepth)), threads_(threads < 1 ? 1 : threads) {}

void AndersonAcceleration::reset() {
  stored_ = 0;
  newest_ = -1;
  havePrevious_ = false;
}

void AndersonAcceleration::restart() { havePrevious_ = false; }

namespace {

// This thread's contiguous share [first, first + count) of `size` rows.
std::pair<Eigen::Index, Eigen::Index> rowBlock(Eigen::Index size) {
  const Eigen::Index threads = omp_get_num_threads(), id = omp_get_thread_num();
  const Eigen::Index first = size * id / threads, last = size * (id + 1) / threads;
  return {first, last - first};
}

}  // namespace

void AndersonAcceleration::next(const Eigen::Ref<const Eigen::VectorXd>& gx,
                                const Eigen::Ref<const Eigen::VectorXd>& f, Eigen::Ref<Eigen::VectorXd> out) {
  if (depth_ == 0) {
    out = gx;
    return;
  }
  const Eigen::Index size = f.size();
  if (dF_.rows() != size) {
    dF_.resize(size, depth_);
    dG_.resize(size, depth_);
    gram_.resize(depth_, depth_);
    previousF_.resize(size);
    previousG_.resize(size);
    reset();
  }
  const bool append = havePrevious_;
  if (append) {
    newest_ = (newest_ + 1) % depth_;
    if (stored_ < depth_) ++stored_;
  }
  // One pass over row blocks, one block per thread: store the new differences, form the new
  // Gram row and dF^T f, and remember (f, G(x)) for the next call. Every operation runs down
  // a column segment, so it vectorizes.
  const int cols = stored_, fresh = newest_;
  double sums[2 * kMaxDepth] = {};  // [gram row | dF^T f]
#pragma omp parallel num_threads(threads_)
  {
    const auto [first, count] = rowBlock(size);
    double gramRow[kMaxDepth] = {}, projected[kMaxDepth] = {};
    const auto fBlock = f.segment(first, count);
    if (append) {
      dF_.col(fresh).segment(first, count) = (fBlock - previousF_.segment(first, count)).cast<float>();
      dG_.col(fresh).segment(first, count) = (gx.segment(first, count) - previousG_.segment(first, count)).cast<float>();
    }
    for (int j = 0; j < cols; ++j) {
      const auto column = dF_.col(j).segment(first, count).cast<double>();
      if (append) gramRow[j] = column.dot(dF_.col(fresh).segment(first, count).cast<double>());
      projected[j] = column.dot(fBlock);
    }
    previousF_.segment(first, count) = fBlock;
    previousG_.segment(first, count) = gx.segment(first, count);
#pragma omp critical
    for (int j = 0; j < cols; ++j) {
      sums[j] += gramRow[j];
      sums[kMaxDepth + j] += projected[j];
    }
  }
  havePrevious_ = true;
  if (cols == 0) {
    out = gx;
    return;
  }
  if (append)
    for (int j = 0; j < cols; ++j) gram_(fresh, j) = gram_(j, fresh) = sums[j];

  Eigen::MatrixXd normal = gram_.topLeftCorner(cols, cols);
  // Tikhonov regularization keeps nearly dependent histories from blowing up gamma.
  normal.diagonal().array() += 1e-10 * normal.trace() + 1e-300;
  const Eigen::VectorXd rhs = Eigen::Map<const Eigen::VectorXd>(sums + kMaxDepth, cols);
  const Eigen::VectorXd gamma = normal.ldlt().solve(rhs);
  if (!gamma.allFinite()) {
    reset();
    out = gx;
    return;
  }
#pragma omp parallel num_threads(threads_)
  {
    const auto [first, count] = rowBlock(size);
    auto block = out.segment(first, count);
    block = gx.segment(first, count);
    for (int j = 0; j < cols; ++j) block -= gamma(j) * dG_.col(j).segment(first, count).cast<double>();
  }
}

}  // namespace ib
