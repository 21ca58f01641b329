#include "testkit/fixtures.h"

#include <cmath>

namespace ib::test {

SolverOptions tightSolverOptions() {
  SolverOptions o;
  o.relativeTolerance = 1e-10;
  o.maxIterations = 3000;
  return o;
}

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
  Multimesh mesh = ib::gluedSquares(n, gap, bulge);
  const double size = boundingDiagonal(mesh.keyPositions(0));
  return {"glued squares", std::move(mesh), size};
}

std::vector<Fixture> allFixtures() {
  std::vector<Fixture> out;
  out.push_back(strip(300, 2));
  out.push_back(strip(300, 4));
  out.push_back(gluedSquares(7, 1.0, 0.3));
  return out;
}

}  // namespace ib::test
