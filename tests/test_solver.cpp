#include "interpolation/interpolator.h"
#include "interpolation/placement.h"
#include "testkit/fixtures.h"
#include "testkit/reference_local_global.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ib;

namespace {

int iterationsToGap(const std::vector<double>& history, double optimum, double gap) {
  for (size_t k = 0; k < history.size(); ++k)
    if (history[k] - optimum <= gap * std::abs(optimum)) return static_cast<int>(k);
  return -1;
}

}  // namespace

TEST_CASE("solver: for plain ARAP the energy never increases from one iteration to the next") {
  const auto f = test::strip(400, 4);
  for (int depth : {0, 10}) {
    SolverOptions o;
    o.relativeTolerance = 1e-8;
    o.andersonDepth = depth;
    Interpolator solver(f.mesh, {}, o);
    for (const Eigen::Vector4d& w : {Eigen::Vector4d(0.5, 0.5, 0, 0), Eigen::Vector4d(0.1, 0.2, 0.3, 0.4)}) {
      const InterpolationResult r = solver.solve(w);
      INFO("Anderson depth " << depth << ", w = " << w.transpose());
      REQUIRE(r.iterations > 3);
      for (size_t k = 1; k < r.energyHistory.size(); ++k)
        REQUIRE(r.energyHistory[k] <= r.energyHistory[k - 1] * (1 + 1e-12));
    }
  }
}

TEST_CASE("solver: with cohesive terms the safeguarded solver never ends worse than it started") {
  const auto f = test::gluedSquares(7, 1.0, 0.3);
  for (double alpha : {0.2, 0.5, 0.8})
    for (double s : {0.2, 0.5, 0.8}) {
      InterpolationParams p;
      p.cohesive.alpha = alpha;
      Interpolator solver(f.mesh, p, SolverOptions{});
      const Eigen::Vector2d w(1 - s, s);
      for (int start = 0; start < 2; ++start) {
        const Eigen::MatrixX2d x0 = f.mesh.keyPositions(start);
        const InterpolationResult r = solver.solve(w, &x0);
        INFO("alpha " << alpha << " s " << s << " start key " << start);
        REQUIRE(r.energy <= r.startEnergy);
        REQUIRE(r.x.allFinite());
      }
    }
}

TEST_CASE("solver: the fixed-matrix formulation reaches the paper's per-iteration-refactorized minimizer") {
  // Anisotropic P (alpha != 1/2) and held pairs: the paper puts P in the global
  // matrix and refactorizes every iteration; we keep H fixed and move P into the local step.
  const auto f = test::gluedSquares(6, 1.0, 0.3);
  InterpolationParams p;
  p.metric = ShapeMetric::kPerKey;  // the paper's energy, as the reference minimizer's
  p.cohesive.alpha = 0.2;
  p.cohesive.timing = CutTiming::kTau;  // the reference is the paper's energy
  p.cohesive.tau = 1e9;                 // every pair held in both solvers
  SolverOptions o;
  o.relativeTolerance = 1e-11;
  o.maxIterations = 5000;
  o.placementStiffness = 1e-9;
  const Eigen::Vector2d w(0.6, 0.4);
  Interpolator solver(f.mesh, p, o);
  const InterpolationResult ours = solver.solve(w);
  REQUIRE(ours.converged);
  const Eigen::MatrixX2d start = 0.6 * f.mesh.keyPositions(0) + 0.4 * f.mesh.keyPositions(1);
  Eigen::MatrixX2d reference = test::referenceLocalGlobal(f.mesh, w, p.cohesive, start, 20000, 1e-13 * f.size);
  // Same gauge for both: the rigid placement the interpolator uses.
  const Eigen::MatrixX2d blend = start;
  PlacementGroups one(f.mesh.vertexCount(), {});
  std::vector<std::pair<int, int>> all;
  for (int v = 1; v < f.mesh.vertexCount(); ++v) all.push_back({0, v});
  one.update(all);
  Eigen::MatrixX2d a = ours.x, b = reference;
  alignGroups(a, blend, one);
  alignGroups(b, blend, one);
  INFO("largest difference / size: " << (a - b).cwiseAbs().maxCoeff() / f.size);
  REQUIRE((a - b).cwiseAbs().maxCoeff() < 1e-5 * f.size);
  // And the same energy: the reference is a stationary point of ours too.
  const double referenceEnergy = solver.evaluate(reference, w).energy;
  REQUIRE(std::abs(ours.energy - referenceEnergy) < 1e-7 * std::abs(referenceEnergy));
}

TEST_CASE("solver: acceleration reaches within 1e-3 of the optimal energy in far fewer iterations") {
  // From a far start (key 0's drawing, at w = (1/2, 1/2)) plain local-global has to carry the
  // rotation along the strip one ring per iteration.
  const auto f = test::strip(1000, 2);
  const Eigen::Vector2d w(0.5, 0.5);
  const Eigen::MatrixX2d start = f.mesh.keyPositions(0);
  SolverOptions tight;
  tight.relativeTolerance = 1e-12;
  tight.maxIterations = 5000;
  SolverOptions plain = tight;
  plain.andersonDepth = 0;
  plain.refactorDistance = 0;
  const InterpolationResult fast = Interpolator(f.mesh, {}, tight).solve(w, &start);
  const InterpolationResult slow = Interpolator(f.mesh, {}, plain).solve(w, &start);
  const double optimum = std::min(fast.energy, slow.energy);
  const int a = iterationsToGap(fast.energyHistory, optimum, 1e-3), b = iterationsToGap(slow.energyHistory, optimum, 1e-3);
  INFO("accelerated " << a << " iterations, plain " << b);
  REQUIRE(a > 0);
  REQUIRE(b > 0);
  REQUIRE(b >= 5 * a);
}

TEST_CASE("solver: stops on the relative residual and reports it") {
  const auto f = test::strip(400, 2);
  SolverOptions o;
  o.relativeTolerance = 1e-3;
  Interpolator solver(f.mesh, {}, o);
  const InterpolationResult r = solver.solve(Eigen::Vector2d(0.3, 0.7));
  REQUIRE(r.converged);
  REQUIRE(r.relativeResidual < 1e-3);
  REQUIRE(r.residualHistory.size() == static_cast<size_t>(r.iterations + 1));
  REQUIRE(r.residualHistory.back() == r.relativeResidual);
  // Every earlier iterate was above the tolerance: the solver did not stop early or late.
  for (size_t k = 0; k + 1 < r.residualHistory.size(); ++k) REQUIRE(r.residualHistory[k] >= 1e-3);
  REQUIRE(r.milliseconds > 0);
  // An iteration cap that is too small is reported as not converged.
  SolverOptions capped = o;
  capped.maxIterations = 2;
  const InterpolationResult c = Interpolator(f.mesh, {}, capped).solve(Eigen::Vector2d(0.3, 0.7));
  REQUIRE_FALSE(c.converged);
  REQUIRE(c.iterations == 2);
}

TEST_CASE("solver: a stale factorization is a preconditioner, not an approximation") {
  // Refactorizing at every new w and never refactorizing converge to the same frame.
  const auto f = test::strip(400, 2);
  SolverOptions exact, stale;
  exact.relativeTolerance = stale.relativeTolerance = 1e-10;
  exact.refactorDistance = 0;
  stale.refactorDistance = 2;  // the factorization of w = (1, 0) serves every frame
  stale.slowFrameIterations = 0;  // even a slow one (at 1e-10 a frame takes more than 40 iterations)
  Interpolator a(f.mesh, {}, exact), b(f.mesh, {}, stale);
  InterpolationResult ra = a.solve(Eigen::Vector2d(1, 0)), rb = b.solve(Eigen::Vector2d(1, 0));
  for (double s : {0.25, 0.5, 0.75}) {
    const Eigen::Vector2d w(1 - s, s);
    ra = a.solve(w, &ra.x);
    rb = b.solve(w, &rb.x);
    INFO("s = " << s);
    REQUIRE(ra.factorizations > 0);
    REQUIRE(rb.factorizations == 0);
    REQUIRE((ra.x - rb.x).cwiseAbs().maxCoeff() < 1e-6 * f.size);
  }
}
