// What changes between an Interpolator's solves without a new setup (a player's sliders): the
// parameters, the stiffness and the cancel flag, with their checks (interpolator.h).
#include "interpolation/interpolator_impl.h"

#include "core/error.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace ib {

void validateInterpolationParams(const InterpolationParams& p) {
  const auto require = [](bool ok, const std::string& field, const std::string& rule) {
    if (!ok) throw InputError("solver option " + field + ": " + rule);
  };
  const CohesiveParams& c = p.cohesive;
  require(std::isfinite(c.lambda) && c.lambda >= 0, "lambda", "must be a finite number >= 0");
  require(c.tau > 0 && !std::isnan(c.tau), "tau", "must be > 0 (infinity: pairs never separate)");
  require(c.alpha >= 0 && c.alpha <= 1, "alpha", "must be in [0, 1]");
  require(c.release >= 0 && c.release <= 1, "release", "must be in [0, 1]");
  require(c.releaseWindow > 0 && c.releaseWindow <= 1, "release_window", "must be in (0, 1]");
  for (const CutRelease& own : c.perTerm) {
    require(std::isnan(own.release) || (own.release >= 0 && own.release <= 1), "a cut's release", "must be in [0, 1]");
    require(std::isnan(own.window) || (own.window > 0 && own.window <= 1), "a cut's release_window", "must be in (0, 1]");
  }
}

void validateStiffness(const Eigen::VectorXd& kappa, int triangleCount) {
  if (kappa.size() != triangleCount)
    throw std::invalid_argument("stiffness: expected " + std::to_string(triangleCount) + " values (one per triangle), got " +
                                std::to_string(kappa.size()));
  // 1e-9 to 1e9: far past what a scene (kappa up to 1e6, painted) and the player's kappa_scale
  // (0.01 to 100) make, and within what H's factorization holds: at 1e300 H overflows.
  for (Eigen::Index k = 0; k < kappa.size(); ++k)
    if (!(kappa(k) >= 1e-9 && kappa(k) <= 1e9)) {
      char value[32];
      std::snprintf(value, sizeof value, "%g", kappa(k));
      throw InputError("stiffness: kappa[" + std::to_string(k) + "] = " + value + " must be a number in [1e-9, 1e9]");
    }
}

void Interpolator::Impl::forgetHistory() {
  anderson_.reset();
  global_->invalidate();
  cohesive_->forgetLetGo();
}

void Interpolator::Impl::checkCutTimings(const InterpolationParams& params) const {
  const size_t terms = cohesive_->terms().size();
  if (!params.cohesive.perTerm.empty() && params.cohesive.perTerm.size() != terms)
    throw std::invalid_argument("cut timings: expected one per cohesive term (" + std::to_string(terms) + "), got " +
                                std::to_string(params.cohesive.perTerm.size()));
}

void Interpolator::Impl::setParameters(const InterpolationParams& params) {
  validateInterpolationParams(params);
  checkCutTimings(params);
  params_ = params;
  updatePlacementWeights();
  cohesive_->setParams(params.cohesive);
  gapPull_->setParams(params.cohesive);
  // H's spring constants follow lambda and alpha, its boundary entries non-overlap; the pattern
  // stays (setSources checks), the factor is redone at the next solve.
  global_->setSources(matrixSources());
  forgetHistory();
}

void Interpolator::Impl::setStiffness(const Eigen::VectorXd& kappa) {
  validateStiffness(kappa, triangleCount());
  Eigen::VectorXd inLayout(kappa.size());
  for (Eigen::Index k = 0; k < kappa.size(); ++k) inLayout(k) = kappa(triangleOriginalOf_[k]);
  deformation_->setStiffness(keys_, inLayout);
  updateStiffnessScale();
  global_->setSources(matrixSources());
  forgetHistory();
}

void Interpolator::forgetHistory() { impl_->forgetHistory(); }
void Interpolator::setParameters(const InterpolationParams& params) { impl_->setParameters(params); }
void Interpolator::setStiffness(const Eigen::VectorXd& kappa) { impl_->setStiffness(kappa); }
void Interpolator::setCancelFlag(const std::atomic<bool>* flag) { impl_->setCancelFlag(flag); }

}  // namespace ib
