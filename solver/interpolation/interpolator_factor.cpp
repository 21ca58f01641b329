// When the interpolation solver factorizes H, and when it updates H's factor instead (see
// interpolator.h and docs/solver.md, "When cohesive pairs engage or let go").
#include "interpolation/interpolator_impl.h"

#include <chrono>

namespace ib {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point started) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
}

}  // namespace

void Interpolator::Impl::refactorize(const Eigen::VectorXd& w, const Eigen::VectorXd& springs,
                               const std::vector<char>& held, InterpolationResult& result) {
  const auto started = std::chrono::steady_clock::now();
  global_->factorize({w, springs, held});
  ++result.factorizations;
  result.factorMilliseconds += millisecondsSince(started);
}

bool Interpolator::Impl::updateFactorization(const std::vector<char>& held, InterpolationResult& result) {
  // A rank-one update's multiply-add takes 4-10 times as long as a factorization's (measured on
  // grids of 1k, 10k and 100k unknowns: 2.8, 2.8 and 6.3 ns against 0.79, 0.53 and 0.63), so the
  // updates are taken while their multiply-adds stay under a tenth of a factorization's.
  if (!options_.updateFactor || global_->updateCost(held) > 0.1 * global_->factorizationCost()) return false;
  const auto started = std::chrono::steady_clock::now();
  if (global_->updateHeld(held)) {
    ++result.factorUpdates;
  } else {
    ++result.factorizations;  // a downdate lost definiteness and H was factorized afresh
  }
  result.factorMilliseconds += millisecondsSince(started);
  return true;
}

bool Interpolator::Impl::followHeld(const Eigen::VectorXd& w, const Eigen::VectorXd& springs,
                                const std::vector<char>& held, InterpolationResult& result) {
  // The factor models the frame but for its pairs, with w within half of refactorDistance.
  if (global_->models({w, springs, global_->held()}, 0.5 * options_.refactorDistance))
    return updateFactorization(held, result);
  refactorize(w, springs, held, result);
  return true;
}

void Interpolator::Impl::ensureFactorization(const Eigen::VectorXd& w, const Eigen::VectorXd& springs,
                                       const std::vector<char>& held, InterpolationResult& result) {
  if (global_->models({w, springs, held}, options_.refactorDistance)) return;
  if (!followHeld(w, springs, held, result)) refactorize(w, springs, held, result);
}

}  // namespace ib
