#include "core/error.h"
#include "interpolation/interpolator.h"
#include "testkit/fixtures.h"
#include "testkit/shape_checks.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <stdexcept>
#include <cmath>
#include <random>

using namespace ib;

namespace {

Eigen::VectorXd unit(int m, int i) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(m);
  w(i) = 1;
  return w;
}

// Rotation angle of y relative to x (both n x 2), by centred Procrustes.
double relativeAngle(const Eigen::MatrixX2d& x, const Eigen::MatrixX2d& y) {
  const Eigen::RowVector2d cx = x.colwise().mean(), cy = y.colwise().mean();
  double dot = 0, cross = 0;
  for (int v = 0; v < x.rows(); ++v) {
    const Eigen::RowVector2d p = x.row(v) - cx, q = y.row(v) - cy;
    dot += p.dot(q);
    cross += p.x() * q.y() - p.y() * q.x();
  }
  return std::atan2(cross, dot);
}

}  // namespace

TEST_CASE("interpolation: w = e_i reproduces key i where it was drawn, on every fixture, placed by the blend or by what stays still") {
  InterpolationParams params;
  params.placement = GENERATE(Placement::kBlend, Placement::kStill);
  for (const auto& f : ib::test::allFixtures()) {
    const int m = f.mesh.keyCount();
    Interpolator solver(f.mesh, params, ib::test::tightSolverOptions());
    for (int i = 0; i < m; ++i) {
      INFO(f.name << ", key " << i << ", placement " << int(params.placement));
      // Start far away: from the next key's drawing, so the solve has real work to do.
      const Eigen::MatrixX2d start = f.mesh.keyPositions((i + 1) % m);
      const InterpolationResult r = solver.solve(unit(m, i), &start);
      REQUIRE(r.converged);
      REQUIRE((r.x - f.mesh.keyPositions(i)).cwiseAbs().maxCoeff() <= 1e-6 * f.size);
    }
  }
}

TEST_CASE("interpolation: keys related by a rigid motion give rigid inbetweens between the placements") {
  const auto f = ib::test::strip(200, 1);
  const Eigen::MatrixX2d X0 = f.mesh.keyPositions(0);
  const double angle = 1.2;
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  const Eigen::RowVector2d shift(3.0, -1.5);
  const Eigen::MatrixX2d X1 = (X0 * R.transpose()).rowwise() + shift;
  Multimesh mesh = f.mesh;
  mesh.addKey(X1, {}, mesh.boundaryVertices(0));
  Interpolator solver(mesh, {}, ib::test::tightSolverOptions());
  InterpolationResult previous = solver.solve(unit(2, 0));
  double previousAngle = 0;
  for (double s = 0.1; s < 0.95; s += 0.1) {
    INFO("s = " << s);
    const Eigen::Vector2d w(1 - s, s);
    previous = solver.solve(w, &previous.x);
    REQUIRE(previous.converged);
    // Zero ARAP energy: the inbetween is congruent to the key (energy in normalized units).
    REQUIRE(previous.interpolationEnergy < 1e-10);
    // Between the placements: centroid on the segment, rotation between 0 and the key's angle,
    // increasing with s.
    const Eigen::RowVector2d centroid = previous.x.colwise().mean();
    const Eigen::RowVector2d expected = (1 - s) * X0.colwise().mean() + s * X1.colwise().mean();
    REQUIRE((centroid - expected).norm() < 1e-6 * f.size);
    const double a = relativeAngle(X0, previous.x);
    REQUIRE(a > previousAngle);
    REQUIRE(a < angle);
    previousAngle = a;
  }
}

TEST_CASE("interpolation: inbetweens move continuously with w, without drift on a round trip") {
  const auto f = ib::test::strip(300, 2);
  Interpolator solver(f.mesh, {}, SolverOptions{});
  std::vector<Eigen::MatrixX2d> forward;
  InterpolationResult r = solver.solve(unit(2, 0));
  const int frames = 20;
  for (int k = 0; k <= frames; ++k) {
    const double s = double(k) / frames;
    r = solver.solve(Eigen::Vector2d(1 - s, s), &r.x);
    forward.push_back(r.x);
  }
  double largestJump = 0;
  for (int k = 1; k <= frames; ++k) largestJump = std::max(largestJump, (forward[k] - forward[k - 1]).cwiseAbs().maxCoeff());
  // A 180-degree bend over 20 frames moves a vertex by at most ~pi * length / 20 per frame.
  REQUIRE(largestJump < 0.25 * f.size);
  // Back again: the same w gives the same frame, whatever path led there.
  for (int k = frames; k >= 0; --k) {
    const double s = double(k) / frames;
    r = solver.solve(Eigen::Vector2d(1 - s, s), &r.x);
    INFO("s = " << s);
    REQUIRE((r.x - forward[k]).cwiseAbs().maxCoeff() < 2e-3 * f.size);
  }
}

TEST_CASE("interpolation: stiffer triangles deform less, in either shape metric") {
  // A strip and the same strip bent almost into a circle: their blend is not a flat metric, so
  // the inbetween must distort somewhere, and kappa decides where. Under the shared metric the
  // rotated keys' triangles of a plain bend average to a half bend, flat: nothing to distribute
  // (stiffness then changes nothing, as it should). Bending a strip stretched along its length
  // leaves some, and there the distortion measured is the shared form's misfit.
  const ShapeMetric metric = GENERATE(ShapeMetric::kPerKey, ShapeMetric::kShared);
  const GridMesh g = rectangleGrid(40, 10, 4.0, 1.0);
  Multimesh uniform(static_cast<int>(g.points.rows()), g.triangles);
  uniform.addKey(g.points, {}, g.boundary);
  uniform.addKey(metric == ShapeMetric::kPerKey ? bendStrip(g.points, 1.9 * M_PI)
                                                : bendStrip(stretchStrip(g.points, 3.0, 0.4), 1.9 * M_PI),
                 {}, g.boundary);
  std::vector<int> left, right;
  Multimesh stiffLeft = uniform;
  for (int k = 0; k < uniform.triangleCount(); ++k) {
    const auto& t = g.triangles[k];
    const bool isLeft = (g.points(t[0], 0) + g.points(t[1], 0) + g.points(t[2], 0)) / 3 < 2.0;
    (isLeft ? left : right).push_back(k);
    if (isLeft) stiffLeft.setStiffness(k, 50.0);
  }
  const Eigen::Vector2d w(0.5, 0.5);
  InterpolationParams params;
  params.metric = metric;
  const auto measure = [&](const Multimesh& mesh, const std::vector<int>& which) {
    const Eigen::MatrixX2d x = Interpolator(mesh, params, ib::test::tightSolverOptions()).solve(w).x;
    double total = 0;
    for (int k : which)
      total += metric == ShapeMetric::kPerKey ? ::test::arapDistortion(mesh, x, w, k) : ::test::sharedMetricDistortion(mesh, x, w, k);
    return total / which.size();
  };
  const double uniformLeft = measure(uniform, left), uniformRight = measure(uniform, right);
  const double stiffLeftLeft = measure(stiffLeft, left), stiffLeftRight = measure(stiffLeft, right);
  INFO("uniform: left " << uniformLeft << " right " << uniformRight << "; stiff left: left " << stiffLeftLeft
                        << " right " << stiffLeftRight);
  REQUIRE(stiffLeftLeft < 0.97 * uniformLeft);
  REQUIRE(stiffLeftRight > 1.03 * uniformRight);
  REQUIRE(stiffLeftLeft < 0.9 * stiffLeftRight);
}

TEST_CASE("interpolation: analytic gradients agree with central finite differences") {
  // ARAP, placement tie (uniform or weighted by stillness) and cohesive terms, including P's
  // dependence on x when alpha != 1/2.
  const double alpha = GENERATE(0.2, 0.5, 0.9);
  const Placement placement = GENERATE(Placement::kBlend, Placement::kStill);
  auto f = ib::test::gluedSquares(5, 1.0, 0.3);
  InterpolationParams params;
  params.cohesive.alpha = alpha;
  params.placement = placement;
  params.cohesive.tau = 1e9;
  Interpolator solver(f.mesh, params, SolverOptions{});
  const Eigen::Vector2d w(0.6, 0.4);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  Eigen::MatrixX2d x = 0.6 * f.mesh.keyPositions(0) + 0.4 * f.mesh.keyPositions(1);
  for (int v = 0; v < x.rows(); ++v) x.row(v) += Eigen::RowVector2d(jitter(rng), jitter(rng));
  const EnergyEvaluation at = solver.evaluate(x, w);
  const double h = 1e-6;
  for (int v = 0; v < x.rows(); v += 3)
    for (int d = 0; d < 2; ++d) {
      Eigen::MatrixX2d plus = x, minus = x;
      plus(v, d) += h;
      minus(v, d) -= h;
      const double numeric = (solver.evaluate(plus, w).energy - solver.evaluate(minus, w).energy) / (2 * h);
      INFO("alpha " << alpha << " placement " << int(placement) << " vertex " << v << " coordinate " << d);
      REQUIRE(at.gradient(v, d) == Approx(numeric).margin(1e-6 * at.gradient.cwiseAbs().maxCoeff()).epsilon(1e-5));
    }
}

TEST_CASE("interpolation: bad weights and wrong-sized positions are the caller's errors, never NaN output") {
  const auto f = ib::test::strip(100, 2);
  Interpolator solver(f.mesh, {}, SolverOptions{});
  REQUIRE_THROWS_WITH(solver.solve(Eigen::Vector3d(0.2, 0.3, 0.5)), Catch::Contains("expected 2 values"));
  REQUIRE_THROWS_WITH(solver.solve(Eigen::Vector2d(1.5, -0.5)), Catch::Contains("w[1]") && Catch::Contains("negative"));
  REQUIRE_THROWS_WITH(solver.solve(Eigen::Vector2d(std::nan(""), 1.0)), Catch::Contains("w[0] is not a finite"));
  REQUIRE_THROWS_WITH(solver.solve(Eigen::Vector2d(0.5, 0.4)), Catch::Contains("sum to"));
  Eigen::MatrixX2d badStart = f.mesh.keyPositions(0);
  badStart(3, 0) = std::numeric_limits<double>::infinity();
  REQUIRE_THROWS_AS(solver.solve(Eigen::Vector2d(0.5, 0.5), &badStart), std::invalid_argument);
  const Eigen::MatrixX2d shortStart = f.mesh.keyPositions(0).topRows(10);
  REQUIRE_THROWS_WITH(solver.solve(Eigen::Vector2d(0.5, 0.5), &shortStart), Catch::Contains("warm start"));
  REQUIRE_THROWS_AS(solver.evaluate(shortStart, Eigen::Vector2d(0.5, 0.5)), std::invalid_argument);
}

TEST_CASE("interpolation: out-of-range parameters name the parameter") {
  const auto f = ib::test::strip(100, 2);
  InterpolationParams p;
  p.cohesive.alpha = 1.5;
  REQUIRE_THROWS_WITH(Interpolator(f.mesh, p, SolverOptions{}), Catch::Contains("alpha"));
  p = {};
  p.cohesive.tau = 0;
  REQUIRE_THROWS_WITH(Interpolator(f.mesh, p, SolverOptions{}), Catch::Contains("tau"));
  SolverOptions o;
  o.relativeTolerance = 0;
  REQUIRE_THROWS_WITH(Interpolator(f.mesh, {}, o), Catch::Contains("relativeTolerance"));
  o = {};
  o.maxIterations = 0;
  REQUIRE_THROWS_WITH(Interpolator(f.mesh, {}, o), Catch::Contains("maxIterations"));
  o = {};
  o.staleHeldIterations = 0;
  REQUIRE_THROWS_WITH(Interpolator(f.mesh, {}, o), Catch::Contains("staleHeldIterations"));
  Multimesh empty(4, {{0, 1, 2}, {0, 2, 3}});
  REQUIRE_THROWS_WITH(Interpolator(empty, {}, SolverOptions{}), Catch::Contains("m = 0"));
}

TEST_CASE("interpolation: keys with zero weight do not change the inbetween") {
  // The 4-key strip's first two keys are the 2-key strip.
  const auto two = ib::test::strip(400, 2), four = ib::test::strip(400, 4);
  const InterpolationResult a = Interpolator(two.mesh, {}, ib::test::tightSolverOptions()).solve(Eigen::Vector2d(0.3, 0.7));
  const InterpolationResult b = Interpolator(four.mesh, {}, ib::test::tightSolverOptions()).solve(Eigen::Vector4d(0.3, 0.7, 0, 0));
  // Only the weak placement tie sees the extra keys (through the shape size that normalizes it).
  REQUIRE((a.x - b.x).cwiseAbs().maxCoeff() < 1e-4 * two.size);
}

TEST_CASE("interpolation: on a mesh large enough for several threads, 2 threads give 1 thread's inbetween, in the caller's numbering") {
  // Over 4000 vertices, so the solver really splits the work (smaller meshes run on one thread).
  const auto f = ib::test::strip(6000, 2);
  REQUIRE(f.mesh.vertexCount() >= 4000);
  SolverOptions one = ib::test::tightSolverOptions(), two = ib::test::tightSolverOptions();
  one.threads = 1;
  two.threads = 2;
  InterpolationParams params;
  params.placement = GENERATE(Placement::kBlend, Placement::kStill);
  INFO("placement " << int(params.placement));
  Interpolator single(f.mesh, params, one), split(f.mesh, params, two);
  REQUIRE(split.threads() == 2);
  Eigen::VectorXd middle(2);
  middle << 0.4, 0.6;
  const InterpolationResult a = single.solve(middle), b = split.solve(middle);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  CHECK((a.x - b.x).cwiseAbs().maxCoeff() <= 1e-6 * f.size);
  // Vertex v of the result is vertex v of the caller's multimesh: w = e_1 gives back X_1 row by row.
  const Eigen::MatrixX2d start = f.mesh.keyPositions(0);
  const InterpolationResult key = split.solve(unit(2, 1), &start);
  REQUIRE(key.converged);
  CHECK((key.x - f.mesh.keyPositions(1)).cwiseAbs().maxCoeff() <= 1e-6 * f.size);
}

TEST_CASE("interpolation: under the shared metric a strip stretched 4x is 2.5x long halfway, the paper's metric shrinks it") {
  // ../shared/shape-averaging.md: stretching by k in one direction, the paper's per-key metric
  // averages lengths harmonically (1.6 at k = 4, halfway), a metric shared by the keys
  // arithmetically (2.5).
  const GridMesh g = rectangleGrid(21, 5, 4.0, 1.0);
  Multimesh mesh(static_cast<int>(g.points.rows()), g.triangles);
  mesh.addKey(g.points, {}, g.boundary);
  Eigen::MatrixX2d stretched = g.points;
  stretched.col(0) *= 4.0;
  mesh.addKey(stretched, {}, g.boundary);
  const auto length = [&](ShapeMetric metric, double w1) {
    InterpolationParams params;
    params.metric = metric;
    const Eigen::MatrixX2d x = Interpolator(mesh, params, ib::test::tightSolverOptions()).solve(Eigen::Vector2d(1 - w1, w1)).x;
    return (x.col(0).maxCoeff() - x.col(0).minCoeff()) / 4.0;
  };
  CHECK(length(ShapeMetric::kShared, 0.5) == Approx(2.5).epsilon(1e-3));
  CHECK(length(ShapeMetric::kPerKey, 0.5) == Approx(1.6).epsilon(1e-2));
  // Even speed: under the shared metric the length grows linearly in w.
  for (double w1 : {0.1, 0.25, 0.75, 0.9}) CHECK(length(ShapeMetric::kShared, w1) == Approx(1 + 3 * w1).epsilon(1e-3));
}

TEST_CASE("interpolation: a frame slow under an H of other weights refactorizes H at its own, once") {
  // A strip and the same strip stretched 8x, thinned 4x and bent, in the paper's metric: the keys'
  // metrics differ so much that H factorized at w = e_0 is a poor model at w = (0.3, 0.7).
  // refactorDistance 2 keeps the stale H by the distance rule; slowFrameIterations decides.
  const GridMesh g = rectangleGrid(41, 9, 8.0, 1.0);
  Multimesh mesh(static_cast<int>(g.points.rows()), g.triangles);
  mesh.addKey(g.points, {}, g.boundary);
  Eigen::MatrixX2d stretched = g.points;
  stretched.col(0) *= 8.0;
  stretched.col(1) *= 0.25;
  mesh.addKey(bendStrip(stretched, 1.5 * M_PI), {}, g.boundary);
  const auto iterations = [&](int slow, int& factorizations) {
    SolverOptions options;
    options.refactorDistance = 2;
    options.slowFrameIterations = slow;
    options.maxIterations = 5000;
    InterpolationParams params;
    params.metric = ShapeMetric::kPerKey;
    Interpolator solver(mesh, params, options);
    solver.solve(Eigen::Vector2d(1, 0));
    const InterpolationResult r = solver.solve(Eigen::Vector2d(0.3, 0.7));
    REQUIRE(r.converged);
    factorizations = r.factorizations;
    return r.iterations;
  };
  int staleFactorizations = 0, refreshedFactorizations = 0;
  const int stale = iterations(0, staleFactorizations);
  const int refreshed = iterations(40, refreshedFactorizations);
  INFO("stale H: " << stale << " iterations, refreshed at 40: " << refreshed);
  REQUIRE(stale > 40);  // the case is slow under the stale H
  CHECK(staleFactorizations == 0);
  CHECK(refreshedFactorizations == 1);
  CHECK(refreshed < stale);
}
