#include "anderson.h"

#include <Eigen/Dense>
#include <vector>

namespace ib {

AndersonAcceleration::AndersonAcceleration(int depth, int threads)
    : depth_(depth < 0 ? 0 : depth), threads_(threads < 1 ? 1 : threads) {}

void AndersonAcceleration::reset() {
  stored_ = 0;
  newest_ = -1;
  havePrevious_ = false;
}

void AndersonAcceleration::restart() { havePrevious_ = false; }

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
  // One pass: store the new differences, update row `newest_` of the Gram matrix, form
  // dF^T f, and remember (f, G(x)) for the next call.
  const int cols = stored_, fresh = newest_;
  std::vector<double> sums(2 * static_cast<size_t>(depth_), 0.0);  // [gram row | dF^T f]
#pragma omp parallel num_threads(threads_)
  {
    std::vector<double> local(2 * static_cast<size_t>(depth_), 0.0);
#pragma omp for schedule(static)
    for (Eigen::Index i = 0; i < size; ++i) {
      float* dFrow = dF_.row(i).data();
      if (append) {
        dFrow[fresh] = static_cast<float>(f(i) - previousF_(i));
        dG_(i, fresh) = static_cast<float>(gx(i) - previousG_(i));
        for (int j = 0; j < cols; ++j) local[j] += double(dFrow[j]) * dFrow[fresh];
      }
      for (int j = 0; j < cols; ++j) local[depth_ + j] += dFrow[j] * f(i);
      previousF_(i) = f(i);
      previousG_(i) = gx(i);
    }
#pragma omp critical
    for (size_t j = 0; j < sums.size(); ++j) sums[j] += local[j];
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
  const Eigen::VectorXd rhs = Eigen::Map<const Eigen::VectorXd>(sums.data() + depth_, cols);
  const Eigen::VectorXd gamma = normal.ldlt().solve(rhs);
  if (!gamma.allFinite()) {
    reset();
    out = gx;
    return;
  }
#pragma omp parallel for schedule(static) num_threads(threads_)
  for (Eigen::Index i = 0; i < size; ++i) {
    const float* dGrow = dG_.row(i).data();
    double v = gx(i);
    for (int j = 0; j < cols; ++j) v -= dGrow[j] * gamma(j);
    out(i) = v;
  }
}

}  // namespace ib
