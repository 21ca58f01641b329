#include "interpolation/interpolator.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>

using namespace ib;

namespace {

// A large square (component 0) and a small square (component 1) that slides, in key 1, from
// the left of the large square to its right, low enough that its straight path grazes the large
// square's top (a quarter of its height deep).
Multimesh crossingSquares() {
  const GridMesh big = rectangleGrid(9, 9, 2.0, 2.0), small = rectangleGrid(5, 5, 0.8, 0.8);
  const int nb = static_cast<int>(big.points.rows()), ns = static_cast<int>(small.points.rows());
  std::vector<Triangle> tris = big.triangles;
  for (const Triangle& t : small.triangles) tris.push_back({t[0] + nb, t[1] + nb, t[2] + nb});
  Eigen::MatrixX2d before(nb + ns, 2), after(nb + ns, 2);
  before.topRows(nb) = big.points;
  after.topRows(nb) = big.points;
  before.bottomRows(ns) = small.points.rowwise() + Eigen::RowVector2d(-1.43, 1.85);
  after.bottomRows(ns) = small.points.rowwise() + Eigen::RowVector2d(2.63, 1.85);
  std::vector<int> boundary = big.boundary;
  for (int v : small.boundary) boundary.push_back(v + nb);
  Multimesh mesh(nb + ns, tris);
  mesh.addKey(before, {}, boundary);
  mesh.addKey(after, {}, boundary);
  return mesh;
}

}  // namespace

int invertedTriangles(const Multimesh& mesh, const Eigen::MatrixX2d& x) {
  int count = 0;
  for (const Triangle& t : mesh.triangles()) count += signedArea(x.row(t[0]), x.row(t[1]), x.row(t[2])) <= 0;
  return count;
}

TEST_CASE("non-overlap: a crossing that overlaps with W_O off leaves no boundary vertex inside with it on") {
  // Played as an animation: frames warm-started one from the next.
  const Multimesh mesh = crossingSquares();
  InterpolationParams off, on;
  on.nonOverlap = true;
  Interpolator free(mesh, off, SolverOptions{}), guarded(mesh, on, SolverOptions{});
  InterpolationResult a = free.solve(Eigen::Vector2d(1, 0)), b = guarded.solve(Eigen::Vector2d(1, 0));
  int overlappingFrames = 0;
  for (int f = 1; f <= 20; ++f) {
    const double s = f / 20.0;
    const Eigen::Vector2d w(1 - s, s);
    a = free.solve(w, &a.x);
    b = guarded.solve(w, &b.x);
    INFO("s = " << s);
    overlappingFrames += free.countOverlaps(a.x, w) > 0;
    REQUIRE(guarded.countOverlaps(b.x, w) == 0);
    REQUIRE(invertedTriangles(mesh, b.x) == 0);
    REQUIRE(b.x.allFinite());
  }
  REQUIRE(overlappingFrames >= 5);
}

TEST_CASE("non-overlap: it changes nothing where nothing overlaps") {
  const auto f = test::strip(300, 2);
  InterpolationParams on;
  on.nonOverlap = true;
  SolverOptions o;
  o.relativeTolerance = 1e-8;
  Interpolator guarded(f.mesh, on, o), free(f.mesh, {}, o);
  const Eigen::Vector2d w(0.5, 0.5);
  const auto a = guarded.solve(w), b = free.solve(w);
  REQUIRE(guarded.countOverlaps(a.x, w) == 0);
  REQUIRE((a.x - b.x).cwiseAbs().maxCoeff() < 1e-6 * f.size);
}
