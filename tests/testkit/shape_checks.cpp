#include "testkit/shape_checks.h"

#include "core/plane_geometry.h"
#include "interpolation/deformation_energy.h"

#include <Eigen/LU>
#include <limits>

namespace test {

namespace {

double distanceToSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return (a + ib::closestParameter(a, b, p) * (b - a) - p).norm();
}

}  // namespace

double distanceToShape(const ib::KeyShape& shape, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const ib::ShapeLoop& loop : shape.loops)
    for (size_t i = 0, n = loop.points.size(); i < n; ++i)
      best = std::min(best, distanceToSegment(loop.points[i], loop.points[(i + 1) % n], p));
  return best;
}

std::vector<int> meshBoundary(const ib::Multimesh& mesh) {
  std::vector<int> out;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (mesh.onBoundary()[v]) out.push_back(v);
  return out;
}

std::vector<std::array<int, 2>> boundaryEdges(const ib::Multimesh& mesh) {
  return mesh.boundaryEdges();
}

double distanceToBoundary(const std::vector<std::array<int, 2>>& edges, const Eigen::MatrixX2d& x,
                          const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : edges) best = std::min(best, distanceToSegment(x.row(a), x.row(b), p));
  return best;
}

double arapDistortion(const ib::Multimesh& mesh, const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, int triangle) {
  const ib::Triangle t = mesh.triangles()[triangle];
  Eigen::Matrix2d D;
  D << x(t[1], 0) - x(t[0], 0), x(t[2], 0) - x(t[0], 0), x(t[1], 1) - x(t[0], 1), x(t[2], 1) - x(t[0], 1);
  double total = 0;
  for (int i = 0; i < mesh.keyCount(); ++i) {
    const Eigen::MatrixX2d X = mesh.keyPositions(i);
    Eigen::Matrix2d rest;
    rest << X(t[1], 0) - X(t[0], 0), X(t[2], 0) - X(t[0], 0), X(t[1], 1) - X(t[0], 1), X(t[2], 1) - X(t[0], 1);
    const Eigen::Matrix2d F = D * rest.inverse();
    total += w(i) * (F - ib::closestRotation(F)).squaredNorm();
  }
  return total;
}

double sharedMetricDistortion(const ib::Multimesh& mesh, const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, int triangle) {
  const ib::Triangle t = mesh.triangles()[triangle];
  const Eigen::Matrix2d D = ib::edgeMatrix(x, t);
  Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
  double area = 0;
  for (int i = 0; i < mesh.keyCount(); ++i) {
    const Eigen::Matrix2d Di = ib::edgeMatrix(mesh.keyPositions(i), t);
    const Eigen::Matrix2d B = Di.inverse();
    M += w(i) * 0.5 * Di.determinant() * B * B.transpose();
    area += w(i) * 0.5 * Di.determinant();
  }
  Eigen::Matrix2d target = Eigen::Matrix2d::Zero();  // D* = sum_i w_i R_i D_i
  for (int i = 0; i < mesh.keyCount(); ++i) {
    const Eigen::Matrix2d Di = ib::edgeMatrix(mesh.keyPositions(i), t);
    target += w(i) * ib::closestRotation(Eigen::Matrix2d(D * M * Di.transpose())) * Di;
  }
  const Eigen::Matrix2d E = D - target;
  return (E * M * E.transpose()).trace() / area;
}

}  // namespace test
