#include "fixtures.h"

#include <cmath>

namespace ib::test {

Fixture strip(int vertices, int keys) {
  Multimesh mesh = benchmarkStrip(vertices, keys);
  const double size = boundingDiagonal(mesh.keyPositions(0));
  return {"strip" + std::to_string(vertices) + "x" + std::to_string(keys), std::move(mesh), size};
}

std::vector<int> seamLeft(int n) {
  std::vector<int> out;
  for (int j = 0; j < n; ++j) out.push_back(j * n + (n - 1));
  return out;
}

std::vector<int> seamRight(int n) {
  std::vector<int> out;
  for (int j = 0; j < n; ++j) out.push_back(n * n + j * n);
  return out;
}

double seamGap(const Eigen::MatrixX2d& x, int n) {
  double gap = 0;
  const auto left = seamLeft(n), right = seamRight(n);
  for (int j = 0; j < n; ++j) gap = std::max(gap, (x.row(left[j]) - x.row(right[j])).norm());
  return gap;
}

Fixture gluedSquares(int n, double gap, double bulge) {
  const GridMesh square = rectangleGrid(n, n, 1.0, 1.0);
  const int count = static_cast<int>(square.points.rows());
  std::vector<Triangle> triangles = square.triangles;
  for (const Triangle& t : square.triangles) triangles.push_back({t[0] + count, t[1] + count, t[2] + count});
  Eigen::MatrixX2d glued(2 * count, 2), apart(2 * count, 2);
  for (int v = 0; v < count; ++v) {
    const double x = square.points(v, 0), y = square.points(v, 1);
    glued.row(v) << x, y;
    glued.row(v + count) << x + 1, y;
    apart.row(v) << x + bulge * x * std::sin(M_PI * y), y;
    apart.row(v + count) << x + 1 + gap - bulge * (1 - x) * std::sin(M_PI * y), y;
  }
  std::vector<int> boundary = square.boundary;
  for (int v : square.boundary) boundary.push_back(v + count);
  std::vector<CohesivePair> pairs;
  const auto left = seamLeft(n), right = seamRight(n);
  for (int j = 0; j + 1 < n; ++j) pairs.push_back({left[j], left[j + 1], right[j], right[j + 1]});
  Multimesh mesh(2 * count, triangles);
  mesh.addKey(glued, pairs, boundary);
  mesh.addKey(apart, {}, boundary);
  return {"glued squares", std::move(mesh), boundingDiagonal(glued)};
}

std::vector<Fixture> allFixtures() {
  std::vector<Fixture> out;
  out.push_back(strip(300, 2));
  out.push_back(strip(300, 4));
  out.push_back(gluedSquares(7, 1.0, 0.3));
  return out;
}

}  // namespace ib::test
