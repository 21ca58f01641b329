// Cut timing by the weights (docs/solver.md, "Cut timing"): the gap pull's gradient, the release
// ramp, and glued squares parting over the release window instead of in one frame.
#include "interpolation/cohesive_energy.h"
#include "interpolation/gap_pull.h"
#include "interpolation/interpolator.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

using namespace ib;

namespace {

constexpr int kSide = 7;  // vertices per side of each glued square

}  // namespace

TEST_CASE("gap pull: its gradient is the energy's derivative, and its rotations follow the cut's neighbourhood") {
  const auto f = test::gluedSquares(kSide, 1.0, 0.3);
  std::vector<Eigen::MatrixX2d> keys = {f.mesh.keyPositions(0), f.mesh.keyPositions(1)};
  CohesiveParams params;
  params.release = 0.5;
  params.releaseWindow = 0.6;
  const CohesiveEnergy cohesive(f.mesh, keys, params);
  GapPull pull(f.mesh, keys, cohesive, params);
  REQUIRE_FALSE(pull.empty());
  Eigen::Matrix2d turn;  // 30 degrees
  turn << std::cos(0.5236), -std::sin(0.5236), std::sin(0.5236), std::cos(0.5236);
  const auto turned = [&](const Eigen::MatrixX2d& x) {
    Eigen::MatrixX2d out = x;
    for (Eigen::Index v = 0; v < x.rows(); ++v) out.row(v) = (turn * x.row(v).transpose()).transpose();
    return out;
  };
  // The open key turned as a whole: its rotations are the turn, and it costs nothing.
  const Eigen::Vector2d open(0, 1);
  const Eigen::MatrixX2d openTurned = turned(keys[1]);
  pull.freezeRotations(openTurned);
  Eigen::MatrixX2d gradient = Eigen::MatrixX2d::Zero(openTurned.rows(), 2);
  CHECK(pull.evaluate(openTurned, open, gradient) == Approx(0).margin(1e-20));
  CHECK(gradient.norm() == Approx(0).margin(1e-9));
  // Between the keys, turned and jittered: the gradient against central differences.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  Eigen::MatrixX2d x = turned(0.5 * (keys[0] + keys[1]));
  for (Eigen::Index v = 0; v < x.rows(); ++v) x.row(v) += Eigen::RowVector2d(jitter(random), jitter(random));
  pull.freezeRotations(x);
  const Eigen::Vector2d w(0.5, 0.5);
  gradient.setZero();
  const double energy = pull.evaluate(x, w, gradient);
  REQUIRE(energy > 0);
  const double h = 1e-6;
  double worst = 0;
  for (Eigen::Index v = 0; v < x.rows(); ++v)
    for (int c = 0; c < 2; ++c) {
      Eigen::MatrixX2d plus = x, minus = x, scratch = Eigen::MatrixX2d::Zero(x.rows(), 2);
      plus(v, c) += h;
      minus(v, c) -= h;
      const double numeric = (pull.evaluate(plus, w, scratch) - pull.evaluate(minus, w, scratch)) / (2 * h);
      worst = std::max(worst, std::abs(numeric - gradient(v, c)));
    }
  INFO("largest gradient error " << worst << " (gradient norm " << gradient.norm() << ")");
  CHECK(worst < 1e-6 * std::max(1.0, gradient.norm()));
}

TEST_CASE("gap pull: the release ramp is whole below the window, gone above it, keeps within [0, 1], and the gap it "
          "leaves starts at rest and grows at most 4/3 as fast as the window's span allows") {
  CohesiveParams p;
  p.release = 0.5;
  p.releaseWindow = 0.3;
  CHECK(releaseRamp(0.0, p) == 1);
  CHECK(releaseRamp(0.35, p) == 1);
  CHECK(releaseRamp(0.65, p) == 0);
  CHECK(releaseRamp(1.0, p) == 0);
  for (double o = 0.35; o < 0.65; o += 0.01) CHECK(releaseRamp(o + 0.01, p) <= releaseRamp(o, p));
  // The gap (1 - r) o, for the default window [0, 1] and this one [0.35, 0.65]: its slope in o is
  // 0 where it parts and at most 4/3 hi / (hi - lo) (docs/solver.md, "Cut timing").
  for (const auto& [releaseAt, windowOf] : {std::pair{0.5, 1.0}, std::pair{0.5, 0.3}}) {
    const double release = releaseAt, window = windowOf;  // lambdas may not capture structured bindings (clang)
    INFO("release " << release << ", window " << window);
    const double lo = release - window / 2, hi = release + window / 2, h = 1e-5;
    const auto gap = [&](double o) { return (1 - releaseRamp(o, release, window)) * o; };
    CHECK(std::abs(gap(lo + h) - gap(lo)) / h < 1e-3);
    double steepest = 0;
    for (double o = lo; o + h <= hi; o += 0.001) steepest = std::max(steepest, (gap(o + h) - gap(o)) / h);
    CHECK(steepest <= 4.0 / 3.0 * hi / (hi - lo) * (1 + 1e-3));
    CHECK(steepest >= 4.0 / 3.0 * hi / (hi - lo) * (1 - 1e-2));
    CHECK(gap(hi) == Approx(hi));
  }
  p.release = 0.95;  // the window would reach past 1: the open key is still open
  CHECK(releaseRamp(1.0, p) == 0);
  p.release = 0.05;  // and before 0: the closed key is still glued
  CHECK(releaseRamp(0.0, p) == 1);
}

TEST_CASE("gap pull: glued squares stay shut before the release window, part over it, and reach the open key's gap, "
          "no frame's move above twice the median") {
  const auto f = test::gluedSquares(kSide, 1.0, 0.3);
  InterpolationParams params;
  params.cohesive.release = 0.5;
  params.cohesive.releaseWindow = 0.8;
  Interpolator solver(f.mesh, params, SolverOptions{});
  InterpolationResult r = solver.solve(Eigen::Vector2d(1, 0));
  std::vector<double> gaps = {test::seamGap(r.x, kSide)};
  std::vector<double> moves;
  for (int k = 1; k <= 40; ++k) {
    const double s = k / 40.0;
    Eigen::MatrixX2d before = r.x;
    r = solver.solve(Eigen::Vector2d(1 - s, s), &r.x);
    INFO("s = " << s << ": " << r.iterations << " iterations, residual " << r.relativeResidual);
    CHECK(r.converged);
    gaps.push_back(test::seamGap(r.x, kSide));
    moves.push_back(std::sqrt((r.x - before).rowwise().squaredNorm().mean()));
  }
  const double drawn = test::seamGap(f.mesh.keyPositions(1), kSide);
  INFO("gaps at s = 0, 0.25, 0.5, 0.75, 1: " << gaps[0] << ", " << gaps[10] << ", " << gaps[20] << ", " << gaps[30] << ", " << gaps[40]
                                               << "; drawn " << drawn);
  CHECK(gaps[4] < 1e-3 * f.size);                  // s = 0.1, before the window (0.1 .. 0.9): shut
  CHECK(gaps[20] > 0.05 * drawn);                  // s = 0.5: parting
  CHECK(gaps[20] < 0.95 * drawn);
  CHECK(gaps[40] == Approx(drawn).margin(1e-3 * f.size));  // the open key's gap
  for (size_t k = 1; k < gaps.size(); ++k) CHECK(gaps[k] >= gaps[k - 1] - 1e-6 * f.size);  // it only opens
  std::vector<double> sorted = moves;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double largest = *std::max_element(moves.begin(), moves.end());
  INFO("largest frame move " << largest << ", median " << median);
  CHECK(largest <= 2 * median);
}

