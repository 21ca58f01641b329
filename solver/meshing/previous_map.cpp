#include "meshing/previous_map.h"

#include "core/box_grid.h"
#include "core/plane_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ib {

namespace {

// The point of triangle (a, b, c) nearest p, as barycentric weights (non-negative, sum 1), and
// its distance from p.
std::pair<Eigen::Vector3d, double> nearestIn(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                                             const Eigen::Vector2d& p) {
  const double area = orient(a, b, c);
  if (std::abs(area) > 0) {
    const Eigen::Vector3d w(orient(b, c, p) / area, orient(c, a, p) / area, orient(a, b, p) / area);
    if (w.minCoeff() >= 0) return {w, 0.0};
  }
  // Outside (or degenerate): the nearest point on the three sides.
  std::pair<Eigen::Vector3d, double> best{Eigen::Vector3d(1, 0, 0), std::numeric_limits<double>::infinity()};
  const Eigen::Vector2d corner[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const Eigen::Vector2d& u = corner[e];
    const Eigen::Vector2d& v = corner[(e + 1) % 3];
    const double t = closestParameter(u, v, p);
    const double d = (u + t * (v - u) - p).norm();
    if (d < best.second) {
      Eigen::Vector3d w = Eigen::Vector3d::Zero();
      w[e] = 1 - t;
      w[(e + 1) % 3] = t;
      best = {w, d};
    }
  }
  return best;
}

}  // namespace

PreviousMapStart::PreviousMapStart(const PreviousMap& previous, const Eigen::MatrixX2d& points, double reach)
    : previous_(&previous) {
  if (!previous.mesh || previous.reference < 0 || previous.reference >= previous.mesh->keyCount()) return;
  const Multimesh& mesh = *previous.mesh;
  const Eigen::MatrixX2d& x = mesh.keyPositions(previous.reference);
  const std::vector<Triangle>& triangles = mesh.triangles();
  if (triangles.empty()) return;
  const int t = static_cast<int>(triangles.size());
  Eigen::MatrixX2d lo(t, 2), hi(t, 2);
  double edges = 0;
  for (int i = 0; i < t; ++i) {
    const Triangle& tri = triangles[static_cast<size_t>(i)];
    lo.row(i) = x.row(tri[0]).cwiseMin(x.row(tri[1])).cwiseMin(x.row(tri[2]));
    hi.row(i) = x.row(tri[0]).cwiseMax(x.row(tri[1])).cwiseMax(x.row(tri[2]));
    edges += (hi.row(i) - lo.row(i)).maxCoeff();
  }
  const BoxGrid grid(lo, hi, std::max(edges / t, 1e-3));
  const int rings = static_cast<int>(std::ceil(reach / grid.cellSize())) + 1;
  triangle_.assign(static_cast<size_t>(points.rows()), -1);
  barycentric_.assign(static_cast<size_t>(points.rows()), Eigen::Vector3d::Zero());
  for (Eigen::Index v = 0; v < points.rows(); ++v) {
    const Eigen::Vector2d p = points.row(v).transpose();
    double best = std::numeric_limits<double>::infinity();
    auto visit = [&](int i) {
      const Triangle& tri = triangles[static_cast<size_t>(i)];
      const auto [w, d] = nearestIn(x.row(tri[0]).transpose(), x.row(tri[1]).transpose(), x.row(tri[2]).transpose(), p);
      if (d < best) best = d, triangle_[static_cast<size_t>(v)] = i, barycentric_[static_cast<size_t>(v)] = w;
    };
    // Ring by ring until a triangle holds p, or the rings left are farther than the best (or reach).
    for (int ring = 0; ring <= rings && best > 0; ++ring) {
      if (ring >= 2 && (ring - 1) * grid.cellSize() > best) break;
      if (!grid.visitRing(p, ring, visit)) break;
    }
    if (!(best <= reach)) return;  // located_ stays false: no start from this map
  }
  located_ = true;
}

bool PreviousMapStart::covers(int key) const {
  return located_ && key >= 0 && key < static_cast<int>(previous_->keyOf.size()) && previous_->keyOf[static_cast<size_t>(key)] >= 0 &&
         previous_->keyOf[static_cast<size_t>(key)] < previous_->mesh->keyCount();
}

Eigen::MatrixX2d PreviousMapStart::positions(int key) const {
  const Multimesh& mesh = *previous_->mesh;
  const Eigen::MatrixX2d& y = mesh.keyPositions(previous_->keyOf[static_cast<size_t>(key)]);
  Eigen::MatrixX2d out(static_cast<Eigen::Index>(triangle_.size()), 2);
  for (size_t v = 0; v < triangle_.size(); ++v) {
    const Triangle& tri = mesh.triangles()[static_cast<size_t>(triangle_[v])];
    const Eigen::Vector3d& w = barycentric_[v];
    out.row(static_cast<Eigen::Index>(v)) = w[0] * y.row(tri[0]) + w[1] * y.row(tri[1]) + w[2] * y.row(tri[2]);
  }
  return out;
}

std::vector<char> foldNeighbourhood(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& positions, int rings) {
  std::vector<char> near(static_cast<size_t>(positions.rows()), 0);
  for (const Triangle& t : triangles)
    if (signedArea(positions.row(t[0]), positions.row(t[1]), positions.row(t[2])) <= 0)
      for (int c : t) near[static_cast<size_t>(c)] = 1;
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<char> grown = near;
    for (const Triangle& t : triangles)
      if (near[static_cast<size_t>(t[0])] || near[static_cast<size_t>(t[1])] || near[static_cast<size_t>(t[2])])
        for (int c : t) grown[static_cast<size_t>(c)] = 1;
    near.swap(grown);
  }
  return near;
}

UntangleResult untangleCarried(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& rest,
                               Eigen::MatrixX2d& positions, const std::vector<char>& locked, const UntangleOptions& options) {
  const std::vector<char> near = foldNeighbourhood(triangles, positions, kFoldRings);
  std::vector<char> held = locked;
  for (size_t v = 0; v < held.size(); ++v)
    if (!near[v]) held[v] = 1;
  Eigen::MatrixX2d local = positions;
  const UntangleResult r = untangle(triangles, rest, local, held, options);
  if (r.injective) {
    positions = local;
    return r;
  }
  return untangle(triangles, rest, positions, locked, options);
}

}  // namespace ib
