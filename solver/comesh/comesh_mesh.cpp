#include "comesh/comesh_mesh.h"

#include <algorithm>

namespace ib {

ComeshMesh::ComeshMesh(const Multimesh& mesh, const ComeshBoundary* boundary)
    : triangles(mesh.triangles()), around(mesh.vertexCount()) {
  const int n = mesh.vertexCount(), m = mesh.keyCount();
  for (int t = 0; t < mesh.triangleCount(); ++t) kappa.push_back(mesh.stiffness(t));
  for (int k = 0; k < m; ++k) {
    keys.push_back(mesh.keyPositions(k));
    cohesive.push_back(mesh.cohesivePairs(k));
    outline.emplace_back(n, 0);
    for (int v : mesh.boundaryVertices(k)) outline[k][v] = 1;
  }
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int v : triangles[t]) around[v].push_back(static_cast<int>(t));
  arc.assign(n, -1);
  next.assign(n, -1);
  previous.assign(n, -1);
  u = Eigen::MatrixXd::Zero(n, m);
  fixed.assign(n, 0);
  held.assign(m, std::vector<char>(n, 0));
  if (!boundary) {
    for (int v = 0; v < n; ++v) fixed[v] = mesh.onBoundary()[v];
    return;
  }
  arc = boundary->arc;
  next = boundary->next;
  for (int v = 0; v < n; ++v) {
    u.row(v).setConstant(boundary->u[v]);
    if (next[v] >= 0) previous[next[v]] = v;
    if (v < static_cast<int>(boundary->pinned.size()) && boundary->pinned[v]) fixed[v] = 1;
  }
  for (int k = 0; k < m && k < static_cast<int>(boundary->heldIn.size()); ++k)
    for (int v = 0; v < n && v < static_cast<int>(boundary->heldIn[k].size()); ++v) held[k][v] = boundary->heldIn[k][v];
  closedIn = boundary->closedIn;
  point = boundary->point;
  chordDeviation = boundary->chordDeviation;
  arcLength = boundary->arcLength;
}

bool ComeshMesh::slides(int v, int k) const {
  return arc[v] >= 0 && !fixed[v] && !held[k][v] && u(v, k) > 0 && point && !closedIn[arc[v]][k];
}

int ComeshMesh::triangleWith(int a, int b) const {
  for (int t : around[a]) {
    const Triangle& c = triangles[t];
    for (int i = 0; i < 3; ++i)
      if (c[i] == a && c[(i + 1) % 3] == b) return t;
  }
  return -1;
}

int ComeshMesh::thirdCorner(int t, int a, int b) const {
  for (int v : triangles[t])
    if (v != a && v != b) return v;
  return -1;
}

std::array<int, 2> ComeshMesh::cutPartner(int a, int b) const {
  for (const auto& pairs : cohesive)
    for (const CohesivePair& p : pairs) {
      if (p.a == a && p.b == b) return {p.c, p.d};
      if (p.a == b && p.b == a) return {p.d, p.c};
      if (p.c == a && p.d == b) return {p.a, p.b};
      if (p.c == b && p.d == a) return {p.b, p.a};
    }
  return {-1, -1};
}

void ComeshMesh::detach(int t) {
  for (int v : triangles[t]) {
    if (v < 0) continue;
    auto& list = around[v];
    list.erase(std::remove(list.begin(), list.end(), t), list.end());
  }
}

void ComeshMesh::setTriangle(int t, const Triangle& corners) {
  detach(t);
  triangles[t] = corners;
  for (int v : corners)
    if (v >= 0) around[v].push_back(t);
}

void ComeshMesh::flip(int a, int b) {
  ++topologyVersion;
  const int t1 = triangleWith(a, b), t2 = triangleWith(b, a);
  const int c = thirdCorner(t1, a, b), d = thirdCorner(t2, b, a);
  const double k = 0.5 * (kappa[t1] + kappa[t2]);
  setTriangle(t1, {c, a, d});
  setTriangle(t2, {d, b, c});
  kappa[t1] = kappa[t2] = k;
}

void ComeshMesh::split(int a, int b, int v) {
  ++topologyVersion;
  ++vertexSetVersion;
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, a}}) {
    const int t = triangleWith(p, q);
    if (t < 0) continue;
    const int c = thirdCorner(t, p, q);
    setTriangle(t, {p, v, c});
    triangles.push_back({-1, -1, -1});
    kappa.push_back(kappa[t]);
    setTriangle(static_cast<int>(triangles.size()) - 1, {v, q, c});
  }
  if (next[b] == a) std::swap(a, b);
  if (next[a] == b) {
    next[a] = v;
    previous[v] = a;
    next[v] = b;
    previous[b] = v;
  }
}

void ComeshMesh::splitPairs(int a, int b, int v, int c, int d, int w) {
  for (auto& pairs : cohesive) {
    const size_t count = pairs.size();
    for (size_t i = 0; i < count; ++i) {
      CohesivePair p = pairs[i];
      if (p.a == b && p.b == a) p = {p.b, p.a, p.d, p.c};
      if (p.c == a && p.d == b) p = {p.c, p.d, p.a, p.b};
      if (p.c == b && p.d == a) p = {p.d, p.c, p.b, p.a};
      if (p.a != a || p.b != b || p.c != c || p.d != d) continue;
      pairs[i] = {a, v, c, w};
      pairs.push_back({v, b, w, d});
    }
  }
}

void ComeshMesh::collapse(int from, int to) {
  ++topologyVersion;
  ++vertexSetVersion;
  if (next[from] == to) {
    previous[to] = previous[from];
    next[previous[from]] = to;
  } else if (previous[from] == to) {
    next[to] = next[from];
    previous[next[from]] = to;
  }
  next[from] = previous[from] = -1;
  const std::vector<int> incident = around[from];
  for (int t : incident) {
    Triangle c = triangles[t];
    if (std::find(c.begin(), c.end(), to) != c.end()) {
      detach(t);
      triangles[t] = {-1, -1, -1};
      continue;
    }
    std::replace(c.begin(), c.end(), from, to);
    setTriangle(t, c);
  }
}

int ComeshMesh::addVertex(const std::vector<Eigen::Vector2d>& positions) {
  const int v = vertexCount();
  for (int k = 0; k < keyCount(); ++k) {
    keys[k].conservativeResize(v + 1, 2);
    keys[k].row(v) = positions[k].transpose();
    outline[k].push_back(0);
    held[k].push_back(0);
  }
  u.conservativeResize(v + 1, Eigen::NoChange);
  u.row(v).setZero();
  around.emplace_back();
  arc.push_back(-1);
  next.push_back(-1);
  previous.push_back(-1);
  fixed.push_back(0);
  return v;
}

void ComeshMesh::compact() {
  std::vector<Triangle> kept;
  std::vector<double> keptKappa;
  for (size_t t = 0; t < triangles.size(); ++t)
    if (triangles[t][0] >= 0) {
      kept.push_back(triangles[t]);
      keptKappa.push_back(kappa[t]);
    }
  triangles = std::move(kept);
  kappa = std::move(keptKappa);
  for (auto& list : around) list.clear();
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int v : triangles[t]) around[v].push_back(static_cast<int>(t));
  ++topologyVersion;  // triangles renumbered
}

Multimesh ComeshMesh::toMultimesh() const {
  std::vector<int> index(vertexCount(), -1);
  int count = 0;
  for (int v = 0; v < vertexCount(); ++v)
    if (!around[v].empty()) index[v] = count++;
  std::vector<Triangle> renumbered;
  std::vector<double> stiffness;
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (triangles[t][0] < 0) continue;
    renumbered.push_back({index[triangles[t][0]], index[triangles[t][1]], index[triangles[t][2]]});
    stiffness.push_back(kappa[t]);
  }
  Multimesh out(count, renumbered);
  for (int k = 0; k < keyCount(); ++k) {
    Eigen::MatrixX2d x(count, 2);
    std::vector<int> boundary;
    for (int v = 0; v < vertexCount(); ++v) {
      if (index[v] < 0) continue;
      x.row(index[v]) = keys[k].row(v);
      if (outline[k][v]) boundary.push_back(index[v]);
    }
    std::vector<CohesivePair> pairs;
    for (const CohesivePair& p : cohesive[k]) pairs.push_back({index[p.a], index[p.b], index[p.c], index[p.d]});
    out.addKey(x, std::move(pairs), std::move(boundary));
  }
  for (size_t t = 0; t < stiffness.size(); ++t) out.setStiffness(static_cast<int>(t), stiffness[t]);
  return out;
}

}  // namespace ib
