#include "testkit/shape_generators.h"

#include "core/error.h"

#include <cmath>

namespace ib {

GridMesh rectangleGrid(int nx, int ny, double width, double height) {
  if (nx < 2 || ny < 2) throw InputError("rectangle grid needs at least 2 x 2 vertices");
  GridMesh g;
  g.points.resize(static_cast<Eigen::Index>(nx) * ny, 2);
  const auto id = [nx](int i, int j) { return j * nx + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      g.points(id(i, j), 0) = width * i / (nx - 1);
      g.points(id(i, j), 1) = height * j / (ny - 1);
      if (i == 0 || j == 0 || i == nx - 1 || j == ny - 1) g.boundary.push_back(id(i, j));
    }
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        g.triangles.push_back({a, b, c});
        g.triangles.push_back({a, c, d});
      } else {
        g.triangles.push_back({a, b, d});
        g.triangles.push_back({b, c, d});
      }
    }
  return g;
}

Eigen::MatrixX2d bendStrip(const Eigen::MatrixX2d& X, double angle) {
  const Eigen::RowVector2d lo = X.colwise().minCoeff(), hi = X.colwise().maxCoeff();
  const double length = hi.x() - lo.x(), cx = 0.5 * (lo.x() + hi.x()), cy = 0.5 * (lo.y() + hi.y());
  const double radius = length / angle;
  Eigen::MatrixX2d out(X.rows(), 2);
  for (int v = 0; v < X.rows(); ++v) {
    const double phi = (X(v, 0) - cx) / radius, r = radius - (X(v, 1) - cy);
    out(v, 0) = cx + r * std::sin(phi);
    out(v, 1) = cy + radius - r * std::cos(phi);
  }
  return out;
}

Eigen::MatrixX2d stretchStrip(const Eigen::MatrixX2d& X, double factor, double taper) {
  const Eigen::RowVector2d lo = X.colwise().minCoeff(), hi = X.colwise().maxCoeff();
  const double length = hi.x() - lo.x(), cy = 0.5 * (lo.y() + hi.y());
  Eigen::MatrixX2d out(X.rows(), 2);
  for (int v = 0; v < X.rows(); ++v) {
    const double s = (X(v, 0) - lo.x()) / length;  // 0..1 along the strip
    out(v, 0) = lo.x() + length * (s + 0.5 * (factor - 1) * s * s);
    out(v, 1) = cy + (X(v, 1) - cy) * (1 - (1 - taper) * s);
  }
  return out;
}

Eigen::MatrixX2d waveStrip(const Eigen::MatrixX2d& X, double amplitude, double periods) {
  const Eigen::RowVector2d lo = X.colwise().minCoeff(), hi = X.colwise().maxCoeff();
  const double length = hi.x() - lo.x();
  Eigen::MatrixX2d out = X;
  for (int v = 0; v < X.rows(); ++v)
    out(v, 1) += amplitude * std::sin(2 * M_PI * periods * (X(v, 0) - lo.x()) / length);
  return out;
}

Multimesh benchmarkStrip(int vertices, int keys) {
  if (keys < 1 || keys > 4) throw InputError("benchmark strip: keys must be 1..4");
  const int ny = std::max(2, static_cast<int>(std::lround(std::sqrt(vertices / 4.0))));
  const int nx = 4 * ny;
  const double height = 1.0, length = 4.0;
  const GridMesh g = rectangleGrid(nx, ny, length, height);
  Multimesh mesh(static_cast<int>(g.points.rows()), g.triangles);
  const Eigen::MatrixX2d shapes[4] = {g.points, bendStrip(g.points, M_PI), stretchStrip(g.points, 2.5, 0.5),
                                      waveStrip(g.points, 0.6, 1.0)};
  for (int k = 0; k < keys; ++k) mesh.addKey(shapes[k], {}, g.boundary);
  return mesh;
}

Multimesh gluedSquares(int side, double gap, double bulge) {
  const GridMesh square = rectangleGrid(side, side, 1.0, 1.0);
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
  for (int j = 0; j + 1 < side; ++j)
    pairs.push_back({j * side + side - 1, (j + 1) * side + side - 1, count + j * side, count + (j + 1) * side});
  Multimesh mesh(2 * count, triangles);
  mesh.addKey(glued, pairs, boundary);
  mesh.addKey(apart, {}, boundary);
  return mesh;
}

}  // namespace ib
