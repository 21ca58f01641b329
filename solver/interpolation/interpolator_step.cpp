// One iteration of the interpolation solver: the local-global step, accelerated by Anderson,
// with its safeguards (docs/solver.md, "Iteration" and "Stopping rule").
#include "interpolation/interpolator_impl.h"

#include <cmath>

namespace ib {

namespace {

Eigen::Map<const Eigen::VectorXd> flat(const Eigen::MatrixX2d& x) { return {x.data(), x.size()}; }
Eigen::Map<Eigen::VectorXd> flatMutable(Eigen::MatrixX2d& x) { return {x.data(), x.size()}; }

}  // namespace

Interpolator::Impl::Step Interpolator::Impl::step(const Frame& frame, const State& s, State& candidate, Eigen::MatrixX2d& plain,
                                      InterpolationResult& result) {
  const double slack = 1e-12 * std::abs(result.startEnergy);  // rounding noise in E
  const auto tryCandidate = [&]() {
    evaluateState(frame, candidate);
    ++result.evaluations;
    return std::isfinite(candidate.energy) && candidate.energy <= s.energy + slack;
  };
  // The plain local-global step G(x) = x - H^{-1} g, placed rigidly.
  global_->factor().step(s.x, s.gradient, plain);
  if (!frame.springs.size()) align(frame, s, plain);
  candidate.x.resize(vertexCount(), 2);
  anderson_.next(flat(plain), flat(s.gradient), flatMutable(candidate.x));
  if (tryCandidate()) return Step::kAccepted;
  if (options_.andersonDepth > 0) {
    anderson_.reset();
    candidate.x = plain;
    if (tryCandidate()) return Step::kAccepted;
  }
  if (s.held != global_->held()) {
    // Cohesive pairs engaged or let go since H was built: H no longer models the energy.
    refactorize(frame.w, frame.springs, s.held, result);
    anderson_.reset();
    return Step::kRefactorized;
  }
  for (double beta = 0.5; beta > 1e-3; beta *= 0.5) {
    candidate.x = s.x + beta * (plain - s.x);
    if (tryCandidate()) return Step::kAccepted;
  }
  // Where placement turned a group far (the gap pull joins pieces that swing), the chord from x
  // to the placed step cuts the turn short and can climb at every length; the step unplaced is a
  // descent direction: fractions of it (chinese-character's strokes stalled on 25 of 68 frames
  // without).
  if (!frame.springs.size()) {
    global_->factor().step(s.x, s.gradient, plain);
    for (double beta = 1; beta > 1e-3; beta *= 0.5) {
      candidate.x = s.x + beta * (plain - s.x);
      if (tryCandidate()) return Step::kAccepted;
    }
  }
  // At a contact (in s or after the step), W_O's targets p_j jump as offenders come and go, so E
  // is discontinuous along the step and no fraction of it may lower E while the plain step still
  // makes progress. There the paper's iteration, which has no line search, goes on: the plain
  // step is taken (measured on assets/circles-in-circles after Comesh: 13 frames stalled short of
  // the stopping rule, 4 of them with up to 25 folded triangles and the circles crossing), or the
  // fraction 1/2 .. 1/16 of it that climbs least: a full step into contact, H modelling no
  // contact, raised E thirtyfold there once and sent the solve wandering.
  if (params_.nonOverlap && contactSteps_) {
    candidate.x = plain;
    evaluateState(frame, candidate);
    ++result.evaluations;
    const bool contact = !s.contacts.empty() || !candidate.contacts.empty();
    if (!contact || !std::isfinite(candidate.energy)) return Step::kStalled;  // E sums every vertex: finite E, finite x
    State least = candidate;
    for (double beta = 0.5; beta >= 0.0625; beta *= 0.5) {
      candidate.x = s.x + beta * (plain - s.x);
      evaluateState(frame, candidate);
      ++result.evaluations;
      if (std::isfinite(candidate.energy) && candidate.energy < least.energy) least = candidate;
    }
    candidate = std::move(least);
    return Step::kAccepted;
  }
  return Step::kStalled;
}

}  // namespace ib
