#include "comesh_energy.h"

#include <Eigen/Dense>
#include <limits>

namespace ib {

namespace {

// Adds the gradient with respect to an edge matrix (2 x 2) to the triangle's three vertices.
void scatter(Eigen::MatrixX2d& gradient, const Triangle& t, const Eigen::Matrix2d& dEdges) {
  gradient.row(t[1]) += dEdges.col(0).transpose();
  gradient.row(t[2]) += dEdges.col(1).transpose();
  gradient.row(t[0]) -= (dEdges.col(0) + dEdges.col(1)).transpose();
}

// adj(E) = det(E) E^-1; linear in E.
Eigen::Matrix2d adjugate(const Eigen::Matrix2d& e) {
  Eigen::Matrix2d a;
  a << e(1, 1), -e(0, 1), -e(1, 0), e(0, 0);
  return a;
}

// d(area)/dE for area = det(E) / 2: half the cofactor matrix.
Eigen::Matrix2d areaGradient(const Eigen::Matrix2d& e) { return 0.5 * adjugate(e).transpose(); }

}  // namespace

double totalArea(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& x) {
  double area = 0;
  for (const Triangle& t : triangles) area += 0.5 * edgeMatrix(x, t).determinant();
  return area;
}

double odtEnergy(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& x, Eigen::MatrixX2d* gradient) {
  double energy = 0;
  for (const Triangle& t : triangles) {
    const Eigen::Matrix2d e = edgeMatrix(x, t);
    const Eigen::Vector2d third = e.col(1) - e.col(0);
    const double area = 0.5 * e.determinant();
    const double squares = e.col(0).squaredNorm() + e.col(1).squaredNorm() + third.squaredNorm();
    energy += area * squares / 12;
    if (!gradient) continue;
    // d squares / d e0 = 2 e0 - 2 (e1 - e0); d squares / d e1 = 2 e1 + 2 (e1 - e0).
    Eigen::Matrix2d dSquares;
    dSquares.col(0) = 2 * e.col(0) - 2 * third;
    dSquares.col(1) = 2 * e.col(1) + 2 * third;
    scatter(*gradient, t, (areaGradient(e) * squares + area * dSquares) / 12);
  }
  return energy;
}

double mipsEnergy(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& xi, const Eigen::MatrixX2d& xj,
                  Eigen::MatrixX2d* gradientI, Eigen::MatrixX2d* gradientJ) {
  double energy = 0;
  for (const Triangle& t : triangles) {
    const Eigen::Matrix2d ei = edgeMatrix(xi, t), ej = edgeMatrix(xj, t);
    const double areaJ = 0.5 * ej.determinant();
    if (!(areaJ > 0)) return std::numeric_limits<double>::infinity();
    const Eigen::Matrix2d adj = adjugate(ei);
    const Eigen::Matrix2d m = ej * adj;  // = 2 a_i J, J the Jacobian from key i to key j
    const double f = m.squaredNorm() / (4 * areaJ);
    energy += f;
    if (gradientJ) scatter(*gradientJ, t, m * adj.transpose() / (2 * areaJ) - f / areaJ * areaGradient(ej));
    if (gradientI) {
      const Eigen::Matrix2d dAdj = ej.transpose() * m / (2 * areaJ);  // d f / d adj(E_i)
      Eigen::Matrix2d dEi;
      dEi << dAdj(1, 1), -dAdj(0, 1), -dAdj(1, 0), dAdj(0, 0);  // adj is linear: chain rule entry by entry
      scatter(*gradientI, t, dEi);
    }
  }
  return energy;
}

double comeshEnergy(const std::vector<Triangle>& triangles, const std::vector<Eigen::MatrixX2d>& keys,
                    const std::vector<double>& odtWeights) {
  const int m = static_cast<int>(keys.size());
  double energy = 0;
  for (int i = 0; i < m; ++i) {
    const double weight = odtWeights.empty() ? 1.0 : odtWeights[i];
    energy += weight * odtEnergy(triangles, keys[i], nullptr) / totalArea(triangles, keys[i]);
    if (m > 1) energy += mipsEnergy(triangles, keys[i], keys[(i + 1) % m], nullptr, nullptr);
  }
  return energy;
}

}  // namespace ib
