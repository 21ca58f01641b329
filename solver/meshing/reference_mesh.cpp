#include "meshing/reference_mesh.h"

#include "core/error.h"
#include "core/plane_geometry.h"
#include "multimesh/spatial_order.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace ib {

namespace {

using Edge = std::pair<int, int>;
Edge undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// The resampled boundary: one point per arc segment start, in loop order.
struct Resampled {
  std::vector<BoundaryTag> tags;
  std::vector<Eigen::Vector2d> positions;
  std::vector<std::vector<int>> loops;  // [loop]: point indices in walking order
  std::vector<int> firstOfArc;          // [arc]: index of its u = 0 point
};

Resampled resample(const SharedBoundary& boundary, int reference) {
  Resampled r;
  r.firstOfArc.resize(boundary.arcs.size());
  for (const std::vector<int>& loopArcs : boundary.loopArcs) {
    r.loops.emplace_back();
    for (int a : loopArcs) {
      r.firstOfArc[a] = static_cast<int>(r.tags.size());
      const int segments = boundary.arcs[a].segments;
      for (int j = 0; j < segments; ++j) {
        r.loops.back().push_back(static_cast<int>(r.tags.size()));
        r.tags.push_back({a, static_cast<double>(j) / segments});
        r.positions.push_back(boundary.at(reference, a, static_cast<double>(j) / segments));
      }
    }
  }
  // Sides of a cut the reference key closes: exact copies, reversed.
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    const BoundaryArc& arc = boundary.arcs[a];
    const auto& closed = arc.closedIn;
    if (arc.partner <= static_cast<int>(a) || std::find(closed.begin(), closed.end(), reference) == closed.end()) continue;
    for (int j = 1; j < arc.segments; ++j)
      r.positions[r.firstOfArc[arc.partner] + arc.segments - j] = r.positions[r.firstOfArc[a] + j];
  }
  return r;
}

class Builder {
 public:
  Builder(const SharedBoundary& boundary, int reference) : boundary_(boundary), reference_(reference) {}

  ReferenceMesh run(const ConformingMeshOptions& options, const std::vector<Eigen::Vector2d>& interior) {
    const Resampled r = resample(boundary_, reference_);
    // Collocated points become one mesher input point ("location").
    std::map<std::pair<double, double>, int> ids;
    std::vector<Eigen::Vector2d> locations;
    std::vector<int> location(r.tags.size());
    for (size_t i = 0; i < r.tags.size(); ++i) {
      const auto [it, fresh] = ids.insert({{r.positions[i].x(), r.positions[i].y()}, static_cast<int>(locations.size())});
      if (fresh) locations.push_back(r.positions[i]);
      location[i] = it->second;
    }
    std::map<Edge, int> uses;
    for (const auto& loop : r.loops)
      for (size_t i = 0; i < loop.size(); ++i) {
        const int a = location[loop[i]], b = location[loop[(i + 1) % loop.size()]];
        if (a == b) throw InputError("the outline doubles back on itself at " + formatPoint(locations[a]));
        ++uses[undirected(a, b)];
      }
    std::vector<std::array<int, 2>> outline, cuts;
    for (const auto& [e, n] : uses) {
      if (n > 2) throw InputError("three boundary pieces share the edge at " + formatPoint(locations[e.first]));
      (n == 1 ? outline : cuts).push_back({e.first, e.second});
    }
    // Interior features: free mesher input points after the boundary's, kept as vertices.
    for (const Eigen::Vector2d& p : interior) {
      mesh_.interior.push_back(static_cast<int>(locations.size()));
      locations.push_back(p);
    }
    ConformingMesh cm = conformingMesh(locations, outline, cuts, options);
    mesh_.points = cm.points;
    mesh_.triangles = cm.triangles;
    origin_.resize(cm.points.size());
    for (size_t v = 0; v < origin_.size(); ++v) origin_[v] = static_cast<int>(v);
    cutOpen(cm.cuts);
    mesh_.tags.assign(mesh_.points.size(), BoundaryTag{});
    pinned_.assign(mesh_.points.size(), 0);
    for (int v : mesh_.interior) pinned_[v] = 1;
    tagBoundary(r, location);
    buildChains();
    mirrorCutSides();
    splitPinnedEdges();
    orderForLocality();
    return std::move(mesh_);
  }

 private:
  // Gives each fan of triangles around a vertex, separated by cut edges, its own vertex.
  void cutOpen(const std::vector<std::array<int, 2>>& cutEdges) {
    std::set<Edge> cuts;
    for (const auto& e : cutEdges) cuts.insert(undirected(e[0], e[1]));
    std::map<int, std::vector<int>> around;  // cut vertex -> incident triangles
    for (const auto& e : cutEdges) around[e[0]], around[e[1]];
    for (size_t t = 0; t < mesh_.triangles.size(); ++t)
      for (int v : mesh_.triangles[t])
        if (around.count(v)) around[v].push_back(static_cast<int>(t));
    for (const auto& [v, tris] : around) {
      std::vector<int> fan(tris.size(), -1);
      int fans = 0;
      for (size_t seed = 0; seed < tris.size(); ++seed) {
        if (fan[seed] >= 0) continue;
        std::vector<size_t> stack{seed};
        fan[seed] = fans;
        while (!stack.empty()) {
          const size_t i = stack.back();
          stack.pop_back();
          for (size_t j = 0; j < tris.size(); ++j)
            if (fan[j] < 0 && sharesUncutEdge(tris[i], tris[j], v, cuts)) fan[j] = fans, stack.push_back(j);
        }
        ++fans;
      }
      for (int f = 1; f < fans; ++f) {
        const int copy = static_cast<int>(mesh_.points.size());
        mesh_.points.push_back(mesh_.points[v]);
        origin_.push_back(origin_[v]);
        for (size_t i = 0; i < tris.size(); ++i)
          if (fan[i] == f)
            for (int& corner : mesh_.triangles[tris[i]])
              if (corner == v) corner = copy;
      }
    }
  }

  bool sharesUncutEdge(int t1, int t2, int v, const std::set<Edge>& cuts) const {
    for (int a : mesh_.triangles[t1])
      if (a != v && std::count(mesh_.triangles[t2].begin(), mesh_.triangles[t2].end(), a) && !cuts.count(undirected(a, v)))
        return true;
    return false;
  }

  // Walks every boundary loop of the mesh from a point only one resampled point sits on, matching
  // resampled points in order; points the mesher added between them get their fraction of the chord.
  void tagBoundary(const Resampled& r, const std::vector<int>& location) {
    std::map<int, int> next;
    std::set<Edge> directed;
    for (const auto& t : mesh_.triangles)
      for (int i = 0; i < 3; ++i) directed.insert({t[i], t[(i + 1) % 3]});
    for (const auto& [a, b] : directed)
      if (!directed.count({b, a}) && !next.insert({a, b}).second)
        throw InputError("the shape pinches to a point at " + formatPoint(mesh_.points[a]) + "; thicken it there");
    std::map<int, int> sharing;
    for (int loc : location) ++sharing[loc];
    std::map<int, int> vertexOfLocation;
    for (size_t v = 0; v < origin_.size(); ++v) vertexOfLocation[origin_[v]] = static_cast<int>(v);
    for (const auto& loop : r.loops) {
      size_t start = 0;
      while (start < loop.size() && sharing[location[loop[start]]] != 1) ++start;
      if (start == loop.size()) throw std::logic_error("reference mesh: a loop lies entirely along cuts");
      int current = vertexOfLocation.at(location[loop[start]]);
      for (size_t step = 0; step < loop.size(); ++step) {
        const int here = loop[(start + step) % loop.size()];
        const int there = loop[(start + step + 1) % loop.size()];
        mesh_.tags[current] = r.tags[here];
        std::vector<int> added;
        int v = next.count(current) ? next.at(current) : -1;
        while (v >= 0 && origin_[v] >= static_cast<int>(sharing.size()) && added.size() < mesh_.points.size())
          added.push_back(v), v = next.count(v) ? next.at(v) : -1;
        if (v < 0 || origin_[v] != location[there])
          throw std::logic_error("reference mesh: boundary walk lost the outline near " + formatPoint(r.positions[here]));
        const bool sameArc = r.tags[there].arc == r.tags[here].arc && r.tags[there].u > r.tags[here].u;
        const double uEnd = sameArc ? r.tags[there].u : 1.0;  // 1: the arc's end (also for a one-arc loop)
        const Eigen::Vector2d p = mesh_.points[current], q = mesh_.points[v];
        for (int s : added) {
          const double t = (mesh_.points[s] - p).norm() / std::max((q - p).norm(), 1e-300);
          mesh_.tags[s] = {r.tags[here].arc, r.tags[here].u + t * (uEnd - r.tags[here].u)};
        }
        current = v;
      }
    }
  }

  void buildChains() {
    mesh_.arcChains.assign(boundary_.arcs.size(), {});
    mesh_.arcEnd.assign(boundary_.arcs.size(), -1);
    for (size_t v = 0; v < mesh_.tags.size(); ++v)
      if (mesh_.tags[v].arc >= 0) mesh_.arcChains[mesh_.tags[v].arc].push_back(static_cast<int>(v));
    for (auto& chain : mesh_.arcChains)
      std::sort(chain.begin(), chain.end(), [&](int a, int b) { return mesh_.tags[a].u < mesh_.tags[b].u; });
    for (const auto& loopArcs : boundary_.loopArcs)
      for (size_t i = 0; i < loopArcs.size(); ++i)
        mesh_.arcEnd[loopArcs[i]] = mesh_.arcChains[loopArcs[(i + 1) % loopArcs.size()]].front();
  }

  // Both sides of every cut get the same fractions (reversed), so they can be paired vertex by vertex.
  void mirrorCutSides() {
    for (size_t a = 0; a < boundary_.arcs.size(); ++a) {
      const int b = boundary_.arcs[a].partner;
      if (b < static_cast<int>(a)) continue;
      for (int pass = 0; pass < 2; ++pass) {
        const int from = pass == 0 ? static_cast<int>(a) : b, to = pass == 0 ? b : static_cast<int>(a);
        const std::vector<int> source = mesh_.arcChains[from];
        for (int v : source) {
          const double u = mesh_.tags[v].u;
          if (u <= 0) continue;
          const double want = 1 - u;
          const auto& chain = mesh_.arcChains[to];
          size_t i = 0;
          while (i + 1 < chain.size() && mesh_.tags[chain[i + 1]].u < want - 1e-9) ++i;
          const bool present = std::any_of(chain.begin(), chain.end(),
                                           [&](int w) { return std::abs(mesh_.tags[w].u - want) <= 1e-9; });
          if (!present) splitBoundaryEdge(to, i, want);
        }
      }
    }
  }

  // Inserts a vertex at fraction u on arc `arc`, between its chain's i-th vertex and the next.
  void splitBoundaryEdge(int arc, size_t i, double u) {
    std::vector<int>& chain = mesh_.arcChains[arc];
    const int x = chain[i];
    const int y = i + 1 < chain.size() ? chain[i + 1] : mesh_.arcEnd[arc];
    const double ux = mesh_.tags[x].u, uy = i + 1 < chain.size() ? mesh_.tags[y].u : 1.0;
    const double t = (u - ux) / (uy - ux);
    const int m = static_cast<int>(mesh_.points.size());
    mesh_.points.push_back((1 - t) * mesh_.points[x] + t * mesh_.points[y]);
    mesh_.tags.push_back({arc, u});
    origin_.push_back(-1);
    for (size_t tri = 0; tri < mesh_.triangles.size(); ++tri) {
      Triangle& f = mesh_.triangles[tri];
      for (int c = 0; c < 3; ++c)
        if (f[c] == x && f[(c + 1) % 3] == y) {
          const int opposite = f[(c + 2) % 3];
          f = {x, m, opposite};
          mesh_.triangles.push_back({m, y, opposite});
          chain.insert(chain.begin() + i + 1, m);
          return;
        }
    }
    throw std::logic_error("reference mesh: no triangle on a boundary edge");
  }

  // Renumbers the vertices along a Hilbert curve and sorts the triangles by their corners, so that
  // neighbours sit close together in memory for every later stage (spatial_order.h).
  void orderForLocality() {
    const std::vector<int> order = hilbertOrder(mesh_.points);
    std::vector<int> index(order.size());
    for (size_t k = 0; k < order.size(); ++k) index[order[k]] = static_cast<int>(k);
    std::vector<Eigen::Vector2d> points(order.size());
    std::vector<BoundaryTag> tags(order.size());
    for (size_t k = 0; k < order.size(); ++k) {
      points[k] = mesh_.points[order[k]];
      tags[k] = mesh_.tags[order[k]];
    }
    mesh_.points = std::move(points);
    mesh_.tags = std::move(tags);
    for (Triangle& t : mesh_.triangles)
      for (int& v : t) v = index[v];
    for (auto& chain : mesh_.arcChains)
      for (int& v : chain) v = index[v];
    for (int& v : mesh_.arcEnd)
      if (v >= 0) v = index[v];
    for (int& v : mesh_.interior) v = index[v];
    std::vector<Triangle> triangles;
    triangles.reserve(mesh_.triangles.size());
    for (int t : triangleOrder(mesh_.triangles)) triangles.push_back(mesh_.triangles[t]);
    mesh_.triangles = std::move(triangles);
  }

  // Splits interior edges whose two ends are both on the boundary, at their midpoints.
  void splitPinnedEdges() {
    for (bool changed = true; changed;) {
      changed = false;
      std::map<Edge, std::vector<int>> faces;
      for (size_t t = 0; t < mesh_.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c)
          faces[undirected(mesh_.triangles[t][c], mesh_.triangles[t][(c + 1) % 3])].push_back(static_cast<int>(t));
      std::vector<char> touched(mesh_.triangles.size(), 0);
      for (const auto& [e, tris] : faces) {
        if (tris.size() != 2 || !pinned(e.first) || !pinned(e.second)) continue;
        if (touched[tris[0]] || touched[tris[1]]) {
          changed = true;
          continue;
        }
        const int m = static_cast<int>(mesh_.points.size());
        mesh_.points.push_back(0.5 * (mesh_.points[e.first] + mesh_.points[e.second]));
        mesh_.tags.push_back({});
        origin_.push_back(-1);
        for (int t : tris) {
          touched[t] = 1;
          Triangle& f = mesh_.triangles[t];
          int c = 0;
          while (!((f[c] == e.first || f[c] == e.second) && (f[(c + 1) % 3] == e.first || f[(c + 1) % 3] == e.second))) ++c;
          const int p = f[c], q = f[(c + 1) % 3], r = f[(c + 2) % 3];
          f = {p, m, r};
          mesh_.triangles.push_back({m, q, r});
          touched.push_back(1);
        }
      }
    }
  }

  // Fixed in every key: on the boundary, or an interior feature.
  bool pinned(int v) const { return mesh_.tags[v].arc >= 0 || (v < static_cast<int>(pinned_.size()) && pinned_[v]); }

  const SharedBoundary& boundary_;
  int reference_;
  std::vector<char> pinned_;  // per vertex before renumbering: an interior feature
  ReferenceMesh mesh_;
  std::vector<int> origin_;  // per vertex: the mesher point it copies (-1 for points added here)
};

}  // namespace

ReferenceMesh meshReference(const SharedBoundary& boundary, int reference, const ConformingMeshOptions& options,
                            const std::vector<Eigen::Vector2d>& interior) {
  return Builder(boundary, reference).run(options, interior);
}

}  // namespace ib
