#include "multimesh/mesh_quality.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace ib {

namespace {

double smallestAngleDegrees(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d p[3] = {a, b, c};
  double smallest = 180;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d u = p[(i + 1) % 3] - p[i], v = p[(i + 2) % 3] - p[i];
    const double angle = std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)) * 180 / M_PI;
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

MapQuality mapQuality(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& from, const Eigen::MatrixX2d& to) {
  MapQuality q;
  double area = 0;
  for (const Triangle& t : triangles) {
    const Eigen::Matrix2d ef = edgeMatrix(from, t), et = edgeMatrix(to, t);
    const double a = 0.5 * ef.determinant();
    const Eigen::Matrix2d j = et * ef.inverse();
    const double det = j.determinant();
    const double mips = det > 0 ? j.squaredNorm() / det : std::numeric_limits<double>::infinity();
    q.mipsMean += a * mips;
    q.mipsMax = std::max(q.mipsMax, mips);
    area += a;
  }
  q.mipsMean /= area;
  return q;
}

}  // namespace

KeyQuality keyQuality(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& x) {
  KeyQuality q;
  q.smallestAngle = 180;
  for (const Triangle& t : triangles) {
    const double angle = smallestAngleDegrees(x.row(t[0]), x.row(t[1]), x.row(t[2]));
    q.smallestAngle = std::min(q.smallestAngle, angle);
    q.meanSmallestAngle += angle;
    q.under20 += angle < 20;
  }
  q.meanSmallestAngle /= std::max<size_t>(triangles.size(), 1);
  q.shareUnder20 = static_cast<double>(q.under20) / std::max<size_t>(triangles.size(), 1);
  return q;
}

MultimeshQuality measureQuality(const Multimesh& mesh) {
  MultimeshQuality q;
  const std::vector<Triangle> triangles = mesh.triangles();
  const int m = mesh.keyCount();
  std::vector<Eigen::MatrixX2d> x;
  for (int k = 0; k < m; ++k) x.push_back(mesh.keyPositions(k));
  for (int k = 0; k < m; ++k) q.keys.push_back(keyQuality(triangles, x[k]));
  const int pairs = m == 2 ? 1 : (m > 2 ? m : 0);
  for (int i = 0; i < pairs; ++i) {
    const int j = (i + 1) % m;
    MapQuality forward = mapQuality(triangles, x[i], x[j]), backward = mapQuality(triangles, x[j], x[i]);
    forward.from = i, forward.to = j, backward.from = j, backward.to = i;
    q.maps.push_back(forward);
    q.maps.push_back(backward);
  }
  return q;
}

}  // namespace ib
