#include "comesh/triangle_shapes.h"
#include "testkit/shape_generators.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace ib;

namespace {

// A 9 x 7 grid (unit spacing) with every vertex jittered by up to 0.3 in every key, so that
// triangles stay positive and edge lengths and angles spread around the bounds below.
ComeshMesh jitteredGrid(int keys, std::mt19937& random) {
  const GridMesh grid = rectangleGrid(9, 7, 8.0, 6.0);
  Multimesh mesh(static_cast<int>(grid.points.rows()), grid.triangles);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int k = 0; k < keys; ++k) {
    Eigen::MatrixX2d x = grid.points;
    for (Eigen::Index v = 0; v < x.rows(); ++v) x.row(v) += Eigen::RowVector2d(jitter(random), jitter(random));
    mesh.addKey(x, {}, grid.boundary);
  }
  return ComeshMesh(mesh, nullptr);
}

double angleAt(const Eigen::Vector2d& corner, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d u = a - corner, v = b - corner;
  return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));  // radians, in [0, pi]
}

// Checks every answer for triangle t in key k against angles and lengths computed directly.
void checkTriangle(const ComeshMesh& mesh, const TriangleShapes& shapes, const TriangleShapeBounds& bounds, int t, int k) {
  const Triangle& tri = mesh.triangles[t];
  Eigen::Vector2d p[3];
  for (int i = 0; i < 3; ++i) p[i] = mesh.keys[k].row(tri[i]).transpose();
  double facing[3];  // facing[i]: the angle at corner i + 2, which faces edge i
  int largest = 0, longEdges = 0, shortEdges = 0, thinEdges = 0;
  for (int i = 0; i < 3; ++i) {
    facing[i] = angleAt(p[(i + 2) % 3], p[i], p[(i + 1) % 3]);
    const double length = (p[(i + 1) % 3] - p[i]).norm();
    if (length > bounds.longLength[k]) longEdges |= 1 << i;
    if (length < bounds.shortLength[k]) shortEdges |= 1 << i;
    if (facing[i] < bounds.thinAngle * M_PI / 180) thinEdges |= 1 << i;
  }
  for (int i = 1; i < 3; ++i)
    if (facing[i] > facing[largest]) largest = i;
  INFO("triangle " << t << ", key " << k);
  CHECK(shapes.largestCosine(t, k) == Approx(std::min(std::cos(facing[largest]), 0.0)).margin(1e-12));
  CHECK(shapes.largestEdge(t, k) == largest);
  CHECK(shapes.longEdges(t, k) == longEdges);
  CHECK(shapes.shortEdges(t, k) == shortEdges);
  CHECK(shapes.thinEdges(t, k) == thinEdges);
}

// The answers over all keys agree with the per-key ones (checked above against angles and
// lengths): the first key with the largest angle gives the worst, the masks hold in every key.
void checkCombined(const ComeshMesh& mesh, const TriangleShapes& shapes, int t) {
  double worst = 1;
  int edge = 0, longEdges = 7, shortEdges = 7, thinEdges = 7;
  for (int k = 0; k < mesh.keyCount(); ++k) {
    if (shapes.largestCosine(t, k) < worst) {
      worst = shapes.largestCosine(t, k);
      edge = shapes.largestEdge(t, k);
    }
    longEdges &= shapes.longEdges(t, k);
    shortEdges &= shapes.shortEdges(t, k);
    thinEdges &= shapes.thinEdges(t, k);
  }
  INFO("triangle " << t);
  CHECK(shapes.worstCosine(t) == worst);
  CHECK(shapes.worstEdge(t) == edge);
  CHECK(shapes.longInEveryKey(t) == longEdges);
  CHECK(shapes.shortInEveryKey(t) == shortEdges);
  CHECK(shapes.thinInEveryKey(t) == thinEdges);
}

void checkAll(const ComeshMesh& mesh, const TriangleShapes& shapes, const TriangleShapeBounds& bounds) {
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    for (int k = 0; k < mesh.keyCount(); ++k) checkTriangle(mesh, shapes, bounds, t, k);
    checkCombined(mesh, shapes, t);
  }
}

}  // namespace

TEST_CASE("triangle shapes: largest angle, long, short and thin edges match a direct computation, per key and over all keys",
          "[comesh]") {
  std::mt19937 random(11);
  ComeshMesh mesh = jitteredGrid(3, random);
  // Thin below 35 degrees (a positive cosine) and below 100 degrees (a negative one): both sides
  // of the squared comparison.
  for (double thinAngle : {35.0, 100.0}) {
    TriangleShapeBounds bounds;
    bounds.shortLength = {0.9, 0.8, 1.0};
    bounds.longLength = {1.2, 1.3, 1.1};
    bounds.thinAngle = thinAngle;
    TriangleShapes shapes(mesh, bounds);
    shapes.refresh();
    checkAll(mesh, shapes, bounds);
  }
}

TEST_CASE("triangle shapes: a moved key and changed corners are recomputed, other keys kept", "[comesh]") {
  std::mt19937 random(12);
  ComeshMesh mesh = jitteredGrid(2, random);
  TriangleShapeBounds bounds;
  bounds.shortLength = {0.9, 0.9};
  bounds.longLength = {1.2, 1.2};
  TriangleShapes shapes(mesh, bounds);
  shapes.refresh();
  checkAll(mesh, shapes, bounds);

  // Key 1 stretches by 1.5 along x: most of its edges become long, and its angles change.
  mesh.keys[1].col(0) *= 1.5;
  shapes.keyMoved(1);
  shapes.refresh();
  checkAll(mesh, shapes, bounds);

  // Rotating a triangle's corners renumbers its edges; a removed slot and a new triangle
  // appended are recomputed too, with no key moving.
  Triangle& rotated = mesh.triangles[5];
  rotated = {rotated[1], rotated[2], rotated[0]};
  mesh.triangles[6] = {-1, -1, -1};
  mesh.triangles.push_back(mesh.triangles[7]);
  ++mesh.topologyVersion;  // as ComeshMesh's operations do
  const int appended = static_cast<int>(mesh.triangles.size()) - 1;
  shapes.refresh();  // reads the removed slot's corners as vertex 0, harmlessly
  for (int k = 0; k < 2; ++k) {
    checkTriangle(mesh, shapes, bounds, 5, k);
    checkTriangle(mesh, shapes, bounds, appended, k);
  }
  checkCombined(mesh, shapes, 5);
  checkCombined(mesh, shapes, appended);
  // Dropping a slot (as compact() does) renumbers every triangle after it; one key moves as well.
  mesh.triangles.erase(mesh.triangles.begin() + 6);
  ++mesh.topologyVersion;
  mesh.keys[0].col(1) *= 0.7;
  shapes.keyMoved(0);
  shapes.refresh();
  checkAll(mesh, shapes, bounds);
}
