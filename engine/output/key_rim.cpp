#include "output/key_rim.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace ib::render {

namespace {

constexpr int kSpokes = 8;  // spokes of the fan round a boundary vertex (45 degrees apart)
constexpr double kPi = 3.14159265358979323846;

Eigen::Vector2d at(const Eigen::MatrixX2d& x, int v) { return x.row(v).transpose(); }

// The outward unit normal of boundary edge {a, b, c} in x: perpendicular to b - a, away from c.
Eigen::Vector2d outwardNormal(const std::array<int, 3>& e, const Eigen::MatrixX2d& x) {
  const Eigen::Vector2d d = at(x, e[1]) - at(x, e[0]);
  Eigen::Vector2d n(d.y(), -d.x());
  const double length = n.norm();
  if (!(length > 0)) return Eigen::Vector2d::Zero();
  n /= length;
  return n.dot(at(x, e[2]) - at(x, e[0])) > 0 ? Eigen::Vector2d(-n) : n;
}

}  // namespace

KeyRim keyRimOf(const Multimesh& mesh, const KeyRimOptions& options) {
  if (!(options.width > 0)) throw std::invalid_argument("render: the key rim's width must be positive");
  KeyRim rim;
  rim.width = options.width;
  std::map<Edge, int> third;  // undirected edge -> the third vertex of a triangle on it
  for (const Triangle& t : mesh.triangles())
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      third[{std::min(a, b), std::max(a, b)}] = t[(i + 2) % 3];
    }
  const int n = mesh.vertexCount();
  std::vector<char> onBoundary(n, 0);
  for (const Edge& e : mesh.boundaryEdges()) {
    const auto found = third.find({std::min(e[0], e[1]), std::max(e[0], e[1])});
    if (found == third.end()) continue;  // an edge of no triangle: nothing to draw beside it
    const int index = static_cast<int>(rim.edges.size());
    rim.edges.push_back({e[0], e[1], found->second});
    const int first = n + static_cast<int>(rim.points.size());
    rim.points.push_back({e[0], index, 0});
    rim.points.push_back({e[1], index, 0});
    rim.triangles.push_back({e[0], e[1], first + 1});
    rim.triangles.push_back({e[0], first + 1, first});
    onBoundary[e[0]] = onBoundary[e[1]] = 1;
  }
  for (int v = 0; v < n; ++v) {
    if (!onBoundary[v]) continue;
    const int first = n + static_cast<int>(rim.points.size());
    for (int s = 0; s < kSpokes; ++s) rim.points.push_back({v, -1, 2 * kPi * s / kSpokes});
    for (int s = 0; s < kSpokes; ++s) rim.triangles.push_back({v, first + s, first + (s + 1) % kSpokes});
  }
  return rim;
}

Eigen::MatrixX2d rimPoints(const KeyRim& rim, const Eigen::MatrixX2d& x) {
  // Each boundary vertex's outward direction: the sum of its edges' outward normals, or where they
  // cancel (a spike's tip, a cut's end) the sum of the directions from its edges' other ends.
  std::vector<Eigen::Vector2d> normal(rim.edges.size());
  std::vector<Eigen::Vector2d> normalSum(static_cast<size_t>(x.rows()), Eigen::Vector2d::Zero()), tangentSum = normalSum;
  for (size_t e = 0; e < rim.edges.size(); ++e) {
    normal[e] = outwardNormal(rim.edges[e], x);
    for (int end = 0; end < 2; ++end) {
      const int v = rim.edges[e][end], other = rim.edges[e][1 - end];
      normalSum[static_cast<size_t>(v)] += normal[e];
      const Eigen::Vector2d away = at(x, v) - at(x, other);
      if (away.norm() > 0) tangentSum[static_cast<size_t>(v)] += away.normalized();
    }
  }
  Eigen::MatrixX2d out(rim.points.size(), 2);
  for (size_t j = 0; j < rim.points.size(); ++j) {
    const KeyRim::Point& p = rim.points[j];
    Eigen::Vector2d direction;
    if (p.edge >= 0) {
      direction = normal[static_cast<size_t>(p.edge)];
    } else {
      Eigen::Vector2d m = normalSum[static_cast<size_t>(p.vertex)];
      if (m.norm() < 0.5) m = tangentSum[static_cast<size_t>(p.vertex)];
      m = m.norm() > 0 ? Eigen::Vector2d(m.normalized()) : Eigen::Vector2d(1, 0);
      const double c = std::cos(p.angle), s = std::sin(p.angle);
      direction = Eigen::Vector2d(c * m.x() - s * m.y(), s * m.x() + c * m.y());
    }
    out.row(static_cast<Eigen::Index>(j)) = (at(x, p.vertex) + rim.width * direction).transpose();
  }
  return out;
}

double keyness(const Eigen::VectorXd& w, double window) {
  if (w.size() == 0 || !(window > 0)) return 0;
  const double t = std::clamp((w.maxCoeff() - (1 - window)) / window, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace ib::render
