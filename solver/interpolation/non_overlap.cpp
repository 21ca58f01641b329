#include "interpolation/non_overlap.h"

#include "core/box_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace ib {

namespace {

// Barycentric coordinates of p in triangle (a, b, c); false for a degenerate triangle.
bool barycentric(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                 double l[3]) {
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double area = cross(b - a, c - a);
  if (std::abs(area) < 1e-300) return false;
  l[0] = cross(b - p, c - p) / area;
  l[1] = cross(c - p, a - p) / area;
  l[2] = cross(a - p, b - p) / area;
  return true;
}

// Parameter t in [0, 1] of the point of segment (a, b) closest to p.
double segmentParameter(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  return len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
}

}  // namespace

NonOverlap::NonOverlap(const Multimesh& mesh, double stiffness)
    : triangles_(mesh.triangles()), stiffness_(stiffness) {
  std::set<std::pair<int, int>> onBoundary;  // each boundary edge as its triangle runs along it
  for (const auto& [from, to] : mesh.boundaryEdges()) onBoundary.insert({from, to});
  for (const auto& [a, b] : mesh.edges())
    if (onBoundary.count({a, b}) || onBoundary.count({b, a})) boundaryEdges_.push_back({a, b});
  boundaryVertex_.assign(mesh.onBoundary().begin(), mesh.onBoundary().end());
  boundaryEdge_.resize(triangles_.size());
  for (size_t t = 0; t < triangles_.size(); ++t) {
    const Triangle& tri = triangles_[t];
    for (int c = 0; c < 3; ++c)  // the edge opposite corner c runs from corner c + 1 to c + 2
      boundaryEdge_[t][c] = onBoundary.count({tri[(c + 1) % 3], tri[(c + 2) % 3]}) > 0;
  }
  partners_.resize(mesh.vertexCount());
  for (int i = 0; i < mesh.keyCount(); ++i) {
    std::vector<int> b = mesh.boundaryVertices(i);
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    keyBoundary_.push_back(b);
    allBoundary_.insert(allBoundary_.end(), b.begin(), b.end());
    for (const CohesivePair& p : mesh.cohesivePairs(i)) {
      partners_[p.a].push_back(p.c);
      partners_[p.c].push_back(p.a);
      partners_[p.b].push_back(p.d);
      partners_[p.d].push_back(p.b);
    }
  }
  std::sort(allBoundary_.begin(), allBoundary_.end());
  allBoundary_.erase(std::unique(allBoundary_.begin(), allBoundary_.end()), allBoundary_.end());
}

std::vector<int> NonOverlap::participants(const ActiveKeys& keys) const {
  std::vector<int> out;
  for (int i : keys.index) out.insert(out.end(), keyBoundary_[i].begin(), keyBoundary_[i].end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool NonOverlap::interiorPoint(const Eigen::Vector2d& p, const Eigen::MatrixX2d& x, int k) const {
  const auto& tri = triangles_[k];
  double l[3];
  if (!barycentric(p, x.row(tri[0]), x.row(tri[1]), x.row(tri[2]), l)) return false;
  constexpr double margin = 1e-9;  // relative to the triangle: points this close count as on it
  int onEdges = 0, edge = -1;
  for (int c = 0; c < 3; ++c) {
    if (l[c] < -margin) return false;
    if (l[c] <= margin) {
      ++onEdges;
      edge = c;
    }
  }
  if (onEdges == 0) return true;
  if (onEdges == 1) return !boundaryEdge_[k][edge];  // on the edge opposite corner `edge`
  for (int c = 0; c < 3; ++c)                        // at the corner whose coordinate is ~1
    if (l[c] > margin) return !boundaryVertex_[tri[c]];
  return false;
}

bool NonOverlap::excluded(int vertex, int other) const {
  if (other == vertex) return true;
  const auto& p = partners_[vertex];
  return std::find(p.begin(), p.end(), other) != p.end();
}

NonOverlap::Grids NonOverlap::buildGrids(const Eigen::MatrixX2d& x) const {
  const int t = static_cast<int>(triangles_.size()), e = static_cast<int>(boundaryEdges_.size());
  Eigen::MatrixX2d lo(t, 2), hi(t, 2), elo(e, 2), ehi(e, 2);
  double extent = 0;
  for (int k = 0; k < t; ++k) {
    const auto& tri = triangles_[k];
    lo.row(k) = x.row(tri[0]).cwiseMin(x.row(tri[1])).cwiseMin(x.row(tri[2]));
    hi.row(k) = x.row(tri[0]).cwiseMax(x.row(tri[1])).cwiseMax(x.row(tri[2]));
    extent += (hi.row(k) - lo.row(k)).norm();
  }
  for (int k = 0; k < e; ++k) {
    elo.row(k) = x.row(boundaryEdges_[k].first).cwiseMin(x.row(boundaryEdges_[k].second));
    ehi.row(k) = x.row(boundaryEdges_[k].first).cwiseMax(x.row(boundaryEdges_[k].second));
  }
  const double cell = std::max(extent / std::max(t, 1), 1e-12);  // about one triangle per cell
  return {BoxGrid(lo, hi, cell), BoxGrid(elo, ehi, cell)};
}

int NonOverlap::coveringTriangle(const Eigen::MatrixX2d& x, const Grids& grids, const Eigen::Vector2d& q, int v) const {
  for (int k : grids.triangles.itemsAt(q)) {
    const auto& tri = triangles_[k];
    if (excluded(v, tri[0]) || excluded(v, tri[1]) || excluded(v, tri[2])) continue;
    if (interiorPoint(q, x, k)) return k;
  }
  return -1;
}

bool NonOverlap::detect(const Eigen::MatrixX2d& x, const Grids& grids, int v, Offender& o) const {
  const Eigen::Vector2d p = x.row(v).transpose();
  const int k = coveringTriangle(x, grids, p, v);
  if (k < 0) return false;
  o = {v, k, p};
  return true;
}

void NonOverlap::findTarget(const Eigen::MatrixX2d& x, const Grids& grids, Offender& o) const {
  // Nearest point on a boundary edge not incident to the vertex that no other triangle covers,
  // searched ring by ring outwards until no closer point can exist.
  const Eigen::Vector2d p = x.row(o.vertex).transpose();
  const BoxGrid& edges = grids.edges;
  double best = std::numeric_limits<double>::infinity();
  for (int ring = 0; best > (ring - 1) * edges.cellSize(); ++ring) {
    const bool inGrid = edges.visitRing(p, ring, [&](int k) {
      const auto [a, b] = boundaryEdges_[k];
      if (excluded(o.vertex, a) || excluded(o.vertex, b)) return;
      const Eigen::Vector2d xa = x.row(a).transpose(), xb = x.row(b).transpose();
      const double t = segmentParameter(p, xa, xb);
      const Eigen::Vector2d q = xa + t * (xb - xa);
      const double d = (q - p).norm();
      if (d < best && coveringTriangle(x, grids, q, o.vertex) < 0) {
        best = d;
        o.target = q;
        o.edgeA = a;
        o.edgeB = b;
        o.t = t;
      }
    });
    if (!inGrid) break;
  }
}

std::vector<NonOverlap::Offender> NonOverlap::offenders(const Eigen::MatrixX2d& x, const std::vector<int>& participants,
                                                        bool withTargets) const {
  if (participants.empty()) return {};
  return offenders(x, buildGrids(x), participants, withTargets);
}

std::vector<NonOverlap::Offender> NonOverlap::offenders(const Eigen::MatrixX2d& x, const Grids& grids,
                                                        const std::vector<int>& participants, bool withTargets) const {
  std::vector<Offender> out;
  Offender o;
  for (int v : participants)
    if (detect(x, grids, v, o)) {
      if (withTargets) findTarget(x, grids, o);
      out.push_back(o);
    }
  return out;
}

double NonOverlap::evaluate(const Eigen::MatrixX2d& x, const std::vector<int>& participants, Eigen::MatrixX2d& gradient,
                            std::vector<std::pair<int, int>>& contacts) const {
  contacts.clear();
  double energy = 0;
  for (const Offender& o : offenders(x, participants, true)) {
    if (o.edgeA < 0) continue;  // no boundary edge to go to (cannot happen on a valid mesh)
    const Eigen::RowVector2d force = stiffness_ * (x.row(o.vertex) - o.target.transpose());
    energy += 0.5 * force.squaredNorm() / stiffness_;
    gradient.row(o.vertex) += force;
    gradient.row(o.edgeA) -= (1 - o.t) * force;
    gradient.row(o.edgeB) -= o.t * force;
    contacts.push_back({o.vertex, triangles_[o.triangle][0]});
    contacts.push_back({o.vertex, o.edgeA});
  }
  return energy;
}

int NonOverlap::project(Eigen::MatrixX2d& x, const std::vector<int>& participants, int passes) const {
  for (int pass = 0; pass < passes; ++pass) {
    const Grids grids = buildGrids(x);
    const auto found = offenders(x, grids, participants, false);
    if (found.empty()) return 0;
    // One offender at a time, each re-checked against the positions moved before it (with this
    // pass's grids), and set past the edge, away from the triangle it was in, by a margin that
    // grows with every pass: that breaks the cycles of two offenders pushing each other back
    // in at a tangent contact.
    const double margin = std::min(0.25, 1e-3 * std::pow(4.0, pass));  // times the edge length
    Offender o;
    for (const Offender& stale : found) {
      if (!detect(x, grids, stale.vertex, o)) continue;
      findTarget(x, grids, o);
      if (o.edgeA < 0) continue;
      const auto& tri = triangles_[o.triangle];
      const Eigen::Vector2d centre = (x.row(tri[0]) + x.row(tri[1]) + x.row(tri[2])).transpose() / 3.0;
      const Eigen::Vector2d edge = (x.row(o.edgeB) - x.row(o.edgeA)).transpose();
      Eigen::Vector2d normal(edge.y(), -edge.x());  // as long as the edge
      if (normal.dot(o.target - centre) < 0) normal = -normal;
      x.row(o.vertex) = (o.target + margin * normal).transpose();
    }
  }
  return countInside(x, participants);
}

int NonOverlap::countInside(const Eigen::MatrixX2d& x, const std::vector<int>& participants) const {
  return static_cast<int>(offenders(x, participants, false).size());
}

}  // namespace ib
