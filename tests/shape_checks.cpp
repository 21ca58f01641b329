#include "shape_checks.h"

#include "plane_geometry.h"

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
  for (auto v : mesh.topology().vertices())
    if (mesh.topology().is_boundary(v)) out.push_back(v.idx());
  return out;
}

std::vector<std::array<int, 2>> boundaryEdges(const ib::Multimesh& mesh) {
  std::vector<std::array<int, 2>> out;
  const ib::TopologyMesh& t = mesh.topology();
  for (auto h : t.halfedges())
    if (t.is_boundary(h)) out.push_back({t.from_vertex_handle(h).idx(), t.to_vertex_handle(h).idx()});
  return out;
}

double distanceToBoundary(const std::vector<std::array<int, 2>>& edges, const Eigen::MatrixX2d& x,
                          const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : edges) best = std::min(best, distanceToSegment(x.row(a), x.row(b), p));
  return best;
}

}  // namespace test
