#include "core/error.h"
#include "multimesh/multimesh.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>
#include <set>
#include <stdexcept>
#include <utility>

using namespace ib;

namespace {

// Two triangles forming the unit square, one key.
Multimesh unitSquare() {
  Multimesh mesh(4, {{0, 1, 2}, {0, 2, 3}});
  Eigen::MatrixX2d X(4, 2);
  X << 0, 0, 1, 0, 1, 1, 0, 1;
  mesh.addKey(X, {}, {0, 1, 2, 3});
  return mesh;
}

}  // namespace

TEST_CASE("multimesh: every fixture validates and keeps one topology across keys") {
  for (const auto& f : test::allFixtures()) {
    INFO(f.name);
    REQUIRE_NOTHROW(f.mesh.validate());
    for (int k = 0; k < f.mesh.keyCount(); ++k) REQUIRE(f.mesh.keyPositions(k).rows() == f.mesh.vertexCount());
  }
}

TEST_CASE("multimesh: key positions and stiffness read back as they were set") {
  Multimesh mesh = unitSquare();
  Eigen::MatrixX2d Y(4, 2);
  Y << 0, 0, 2, 0, 2, 1, 0, 1;
  mesh.addKey(Y, {}, {});
  mesh.setStiffness(1, 7.5);
  REQUIRE(mesh.keyCount() == 2);
  REQUIRE((mesh.keyPositions(1) - Y).norm() == 0.0);
  REQUIRE(mesh.stiffness(0) == 1.0);
  REQUIRE(mesh.stiffness(1) == 7.5);
}

TEST_CASE("multimesh: a mesh with no keys is rejected") {
  Multimesh mesh(4, {{0, 1, 2}, {0, 2, 3}});
  REQUIRE_THROWS_WITH(mesh.validate(), Catch::Contains("no keys"));
}

TEST_CASE("multimesh: a degenerate or inverted rest triangle names the triangle and key") {
  Multimesh mesh = unitSquare();
  Eigen::MatrixX2d flat(4, 2);
  flat << 0, 0, 1, 0, 2, 0, 0, 1;  // triangle 0 collapses onto the x axis
  mesh.addKey(flat, {}, {});
  REQUIRE_THROWS_WITH(mesh.validate(), Catch::Contains("triangle 0") && Catch::Contains("key 1"));
}

TEST_CASE("multimesh: a wrong position count is a caller's error, bad indices and non-finite values are input errors") {
  Multimesh mesh = unitSquare();
  REQUIRE_THROWS_AS(mesh.addKey(Eigen::MatrixX2d::Zero(3, 2), {}, {}), std::invalid_argument);
  REQUIRE_THROWS_AS(mesh.setStiffness(2, 1.0), std::invalid_argument);
  REQUIRE_THROWS_AS(Multimesh(3, {{0, 1, 5}}), InputError);
  REQUIRE_THROWS_AS(Multimesh(3, {{0, 1, 1}}), InputError);
  Eigen::MatrixX2d X = mesh.keyPositions(0);
  X(2, 1) = std::nan("");
  mesh.setKeyPositions(0, X);
  REQUIRE_THROWS_WITH(mesh.validate(), Catch::Contains("non-finite"));
}

TEST_CASE("multimesh: edges once each, boundary edges with the shape on their left, boundary flags and loops") {
  // A 3 x 3 grid of vertices (0..8, row by row, y up) in 8 counter-clockwise triangles: one
  // interior vertex (4), 16 edges, 8 of them on the boundary, one loop.
  std::vector<Triangle> triangles;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      const int v = 3 * r + c;
      triangles.push_back({v, v + 1, v + 4});
      triangles.push_back({v, v + 4, v + 3});
    }
  Multimesh grid(9, triangles);
  Eigen::MatrixX2d X(9, 2);
  for (int v = 0; v < 9; ++v) X.row(v) << v % 3, v / 3;
  grid.addKey(X, {}, {});
  CHECK(grid.edges().size() == 16);
  std::set<std::pair<int, int>> seen;
  for (const Edge& e : grid.edges()) CHECK(seen.insert({std::min(e[0], e[1]), std::max(e[0], e[1])}).second);
  REQUIRE(grid.boundaryEdges().size() == 8);
  const Eigen::Vector2d centre(1, 1);
  for (const Edge& e : grid.boundaryEdges())  // the centre lies to the left of every boundary edge
    CHECK(signedArea(X.row(e[0]), X.row(e[1]), centre) > 0);
  for (int v = 0; v < 9; ++v) CHECK(grid.onBoundary()[v] == (v != 4));
  const auto loops = grid.boundaryLoops();
  REQUIRE(loops.size() == 1);
  CHECK(loops[0].size() == 8);
}

TEST_CASE("multimesh: a non-manifold triangle is rejected") {
  // Three triangles on one edge (0, 1).
  REQUIRE_THROWS_WITH(Multimesh(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}), Catch::Contains("triangle 2"));
}

TEST_CASE("multimesh: cohesive pairs must name mesh edges collocated in their key") {
  auto f = test::gluedSquares(4, 1.0, 0.2);
  REQUIRE_NOTHROW(f.mesh.validate());
  Multimesh mesh = f.mesh;
  // The same pairs on the apart key are not collocated there.
  mesh.addKey(mesh.keyPositions(1), mesh.cohesivePairs(0), {});
  REQUIRE_THROWS_WITH(mesh.validate(), Catch::Contains("key 2 cohesive pair 0") && Catch::Contains("collocated"));
  Multimesh notEdge = f.mesh;
  notEdge.addKey(notEdge.keyPositions(0), {{0, 5, 1, 6}}, {});
  REQUIRE_THROWS_WITH(notEdge.validate(), Catch::Contains("not in the mesh"));
  Multimesh kappa = f.mesh;
  kappa.setStiffness(3, -1.0);
  REQUIRE_THROWS_WITH(kappa.validate(), Catch::Contains("triangle 3") && Catch::Contains("kappa"));
}
