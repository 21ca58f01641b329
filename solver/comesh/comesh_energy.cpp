#include "comesh/comesh_energy.h"

#include <Eigen/Dense>
#include <algorithm>
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

// Key i's part of eq. 8 without gradients: ODT(X_i), area(X_i) and MIPS(X_i, X_j), with the
// smallest triangle area in X_j (MIPS is infinite unless it is positive).
struct KeyPart {
  double odt = 0, area = 0, mips = 0;
  double smallestNextArea = std::numeric_limits<double>::infinity();
};

// One pass over `count` triangles (corners three ints each; a negative corner marks a deleted
// triangle, which counts nothing) with gathered loads, which the compiler vectorizes: the
// objective is evaluated once per outer iteration for every key. The same sums as odtEnergy,
// totalArea and mipsEnergy, in another order.
KeyPart keyPart(const int* __restrict corners, size_t count, const double* __restrict xi, const double* __restrict yi,
                const double* __restrict xj, const double* __restrict yj) {
  double odt = 0, area = 0, mips = 0, smallest = std::numeric_limits<double>::infinity();
#pragma omp simd reduction(+ : odt, area, mips) reduction(min : smallest)
  for (size_t t = 0; t < count; ++t) {
    const bool live = corners[3 * t] >= 0;
    const int a = live ? corners[3 * t] : 0, b = live ? corners[3 * t + 1] : 0, c = live ? corners[3 * t + 2] : 0;
    // Edge matrices: entry (r, c) is coordinate r of edge c (x_b - x_a, x_c - x_a).
    const double e00 = xi[b] - xi[a], e01 = xi[c] - xi[a], e10 = yi[b] - yi[a], e11 = yi[c] - yi[a];
    const double j00 = xj[b] - xj[a], j01 = xj[c] - xj[a], j10 = yj[b] - yj[a], j11 = yj[c] - yj[a];
    const double areaI = 0.5 * (e00 * e11 - e01 * e10), areaJ = 0.5 * (j00 * j11 - j01 * j10);
    const double t0 = e01 - e00, t1 = e11 - e10;  // the third edge
    const double squares = e00 * e00 + e10 * e10 + e01 * e01 + e11 * e11 + t0 * t0 + t1 * t1;
    // E_j adj(E_i), adj(E_i) = [e11 -e01; -e10 e00]
    const double m00 = j00 * e11 - j01 * e10, m01 = j01 * e00 - j00 * e01;
    const double m10 = j10 * e11 - j11 * e10, m11 = j11 * e00 - j10 * e01;
    const double f = (m00 * m00 + m01 * m01 + m10 * m10 + m11 * m11) / (live ? 4 * areaJ : 1.0);
    odt += live ? areaI * squares / 12 : 0.0;
    area += live ? areaI : 0.0;
    mips += live ? f : 0.0;
    smallest = std::min(smallest, live ? areaJ : std::numeric_limits<double>::infinity());
  }
  return {odt, area, mips, smallest};
}

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
  static_assert(sizeof(Triangle) == 3 * sizeof(int), "corners are read as one int array");
  const int m = static_cast<int>(keys.size());
  double energy = 0;
  for (int i = 0; i < m; ++i) {
    const Eigen::MatrixX2d& next = keys[(i + 1) % m];  // key i itself for one key (its MIPS is not used)
    const KeyPart part = keyPart(triangles.data()->data(), triangles.size(), keys[i].col(0).data(),
                                 keys[i].col(1).data(), next.col(0).data(), next.col(1).data());
    const double weight = odtWeights.empty() ? 1.0 : odtWeights[i];
    energy += weight * part.odt / part.area;
    if (m == 1) continue;
    if (!(part.smallestNextArea > 0)) return std::numeric_limits<double>::infinity();
    energy += part.mips;
  }
  return energy;
}

}  // namespace ib
