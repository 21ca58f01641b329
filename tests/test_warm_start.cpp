#include "animation/warm_start.h"
#include "interpolation/interpolator.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>

using namespace ib;

namespace {

Eigen::VectorXd weights(double s) { return Eigen::Vector2d(1 - s, s); }

}  // namespace

TEST_CASE("warm start: nothing before the first frame, the last solution after it") {
  WarmStartPredictor p;
  CHECK_FALSE(p.predict(weights(0.1)).has_value());
  const Eigen::MatrixX2d x = Eigen::MatrixX2d::Random(5, 2);
  p.remember(weights(0.0), x);
  REQUIRE(p.predict(weights(0.1)).has_value());
  CHECK((*p.predict(weights(0.1)) - x).norm() == 0.0);
  p.clear();
  CHECK_FALSE(p.predict(weights(0.1)).has_value());
}

TEST_CASE("warm start: a path linear in w is extrapolated exactly, at any step length") {
  const Eigen::MatrixX2d a = Eigen::MatrixX2d::Random(7, 2), b = Eigen::MatrixX2d::Random(7, 2);
  const auto path = [&](double s) -> Eigen::MatrixX2d { return a + s * b; };
  WarmStartPredictor p;
  p.remember(weights(0.2), path(0.2));
  p.remember(weights(0.3), path(0.3));
  for (double next : {0.3, 0.35, 0.4, 0.5}) CHECK((*p.predict(weights(next)) - path(next)).norm() < 1e-12);
}

TEST_CASE("warm start: a turn in weight space or a jump back does not extrapolate past the last frame") {
  const Eigen::MatrixX2d x0 = Eigen::MatrixX2d::Zero(3, 2), x1 = Eigen::MatrixX2d::Ones(3, 2);
  WarmStartPredictor p;
  p.remember(Eigen::Vector3d(1, 0, 0), x0);
  p.remember(Eigen::Vector3d(0.9, 0.1, 0), x1);
  // Orthogonal to the last step in the plane sum w = 1 (0.1 towards key 2, 0.05 back each way).
  CHECK((*p.predict(Eigen::Vector3d(0.95, 0.05, 0.0) + Eigen::Vector3d(-0.05, -0.05, 0.1)) - x1).norm() < 1e-12);
  CHECK((*p.predict(Eigen::Vector3d(1, 0, 0)) - x1).norm() < 1e-12);             // back: t < 0, clamped
  CHECK((*p.predict(Eigen::Vector3d(0, 1, 0)) - (x1 + 2 * (x1 - x0))).norm() < 1e-12);  // far: t = 9, clamped
}

TEST_CASE("warm start: on a bend sweep the extrapolated start is at least twice as close as the last frame") {
  const auto f = test::strip(600, 2);
  SolverOptions tight;
  tight.relativeTolerance = 1e-9;
  Interpolator solver(f.mesh, {}, tight);
  WarmStartPredictor p;
  const int frames = 8;
  Eigen::MatrixX2d last;
  for (int k = 0; k <= frames; ++k) {
    const Eigen::VectorXd w = weights(double(k) / frames);
    const std::optional<Eigen::MatrixX2d> start = p.predict(w);
    const InterpolationResult r = solver.solve(w, start ? &*start : nullptr);
    REQUIRE(r.converged);
    if (k >= 2) {
      INFO("frame " << k);
      CHECK((*start - r.x).norm() < 0.5 * (last - r.x).norm());
    }
    p.remember(w, r.x);
    last = r.x;
  }
}
