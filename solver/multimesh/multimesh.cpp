#include "multimesh/multimesh.h"

#include "core/error.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>

namespace ib {

namespace {

std::string vertexName(int v) { return "vertex " + std::to_string(v); }
std::string keyName(int k) { return "key " + std::to_string(k); }

}  // namespace

Eigen::Matrix2d edgeMatrix(const Eigen::MatrixX2d& x, const Triangle& tri) {
  Eigen::Matrix2d d;
  d.col(0) = (x.row(tri[1]) - x.row(tri[0])).transpose();
  d.col(1) = (x.row(tri[2]) - x.row(tri[0])).transpose();
  return d;
}

double signedArea(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2) {
  const Eigen::Vector2d e1 = p1 - p0, e2 = p2 - p0;
  return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

double boundingDiagonal(const Eigen::MatrixX2d& points) {
  if (points.rows() < 2) return 0.0;
  return (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
}

Multimesh renumbered(const Multimesh& mesh, const std::vector<int>& vertexOrder) {
  const int n = mesh.vertexCount();
  if (static_cast<int>(vertexOrder.size()) != n) throw std::invalid_argument("renumbered: order of the wrong size");
  std::vector<int> newIndex(n, -1);
  for (int k = 0; k < n; ++k) {
    if (vertexOrder[k] < 0 || vertexOrder[k] >= n || newIndex[vertexOrder[k]] >= 0)
      throw std::invalid_argument("renumbered: order is not a permutation");
    newIndex[vertexOrder[k]] = k;
  }
  std::vector<Triangle> triangles = mesh.triangles();
  for (Triangle& tri : triangles)
    for (int& v : tri) v = newIndex[v];
  Multimesh out(n, triangles);
  for (int t = 0; t < mesh.triangleCount(); ++t) out.setStiffness(t, mesh.stiffness(t));
  for (int i = 0; i < mesh.keyCount(); ++i) {
    const Eigen::MatrixX2d X = mesh.keyPositions(i);
    Eigen::MatrixX2d positions(n, 2);
    for (int k = 0; k < n; ++k) positions.row(k) = X.row(vertexOrder[k]);
    std::vector<CohesivePair> pairs = mesh.cohesivePairs(i);
    for (CohesivePair& p : pairs) p = {newIndex[p.a], newIndex[p.b], newIndex[p.c], newIndex[p.d]};
    std::vector<int> boundary = mesh.boundaryVertices(i);
    for (int& v : boundary) v = newIndex[v];
    out.addKey(positions, std::move(pairs), std::move(boundary));
  }
  return out;
}

Multimesh::Multimesh(int vertexCount, const std::vector<Triangle>& triangles)
    : vertexCount_(vertexCount), triangles_(triangles), kappa_(triangles.size(), 1.0) {
  if (vertexCount < 3) throw InputError("multimesh: needs at least 3 vertices, got " + std::to_string(vertexCount));
  if (triangles.empty()) throw InputError("multimesh: has no triangles");
  // OpenMesh checks that the triangles make a manifold, consistently oriented surface, and
  // numbers the edges; nothing of it is kept but the derived lists.
  OpenMesh::TriMesh_ArrayKernelT<> mesh;
  for (int v = 0; v < vertexCount; ++v) mesh.add_vertex(OpenMesh::TriMesh_ArrayKernelT<>::Point(0, 0, 0));
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (int v : tri) {
      if (v < 0 || v >= vertexCount)
        throw InputError("multimesh: triangle " + std::to_string(t) + " refers to " + vertexName(v) +
                         " of " + std::to_string(vertexCount));
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw InputError("multimesh: triangle " + std::to_string(t) + " repeats a vertex");
    const auto face = mesh.add_face(mesh.vertex_handle(tri[0]), mesh.vertex_handle(tri[1]),
                                    mesh.vertex_handle(tri[2]));
    if (!face.is_valid())
      throw InputError("multimesh: triangle " + std::to_string(t) +
                       " makes the topology non-manifold or is inconsistently oriented");
  }
  edges_.reserve(mesh.n_edges());
  for (auto e : mesh.edges()) edges_.push_back({e.v0().idx(), e.v1().idx()});
  onBoundary_.assign(vertexCount, 0);
  for (auto v : mesh.vertices()) onBoundary_[v.idx()] = v.is_boundary();
  for (auto h : mesh.halfedges())
    if (h.is_boundary()) boundaryEdges_.push_back({h.to().idx(), h.from().idx()});  // the triangle's halfedge
}

std::vector<std::vector<int>> Multimesh::boundaryLoops() const {
  std::vector<int> next(vertexCount_, -1);
  for (const Edge& e : boundaryEdges_) next[e[0]] = e[1];  // manifold: one boundary edge leaves a vertex
  std::vector<char> seen(vertexCount_, 0);
  std::vector<std::vector<int>> loops;
  for (const Edge& e : boundaryEdges_) {
    if (seen[e[0]]) continue;
    std::vector<int> loop;
    for (int v = e[0]; v >= 0 && !seen[v]; v = next[v]) {
      seen[v] = 1;
      loop.push_back(v);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

int Multimesh::addKey(const Eigen::MatrixX2d& positions, std::vector<CohesivePair> cohesive,
                      std::vector<int> boundary) {
  const int key = keyCount();
  if (positions.rows() != vertexCount())
    throw std::invalid_argument("multimesh: " + keyName(key) + " has " + std::to_string(positions.rows()) +
                                " positions for " + std::to_string(vertexCount()) + " vertices");
  keys_.push_back({positions, std::move(cohesive), std::move(boundary)});
  return key;
}

void Multimesh::setKeyPositions(int key, const Eigen::MatrixX2d& positions) {
  if (positions.rows() != vertexCount())
    throw std::invalid_argument("multimesh: " + keyName(key) + " positions have the wrong size");
  keys_.at(key).positions = positions;
}

void Multimesh::setStiffness(int triangle, double kappa) {
  if (triangle < 0 || triangle >= triangleCount())
    throw std::invalid_argument("multimesh: stiffness for triangle " + std::to_string(triangle) + " out of range");
  kappa_[triangle] = kappa;
}

Eigen::VectorXd Multimesh::stiffnesses() const {
  return Eigen::Map<const Eigen::VectorXd>(kappa_.data(), triangleCount());
}

void Multimesh::validate() const {
  if (keyCount() < 1) throw InputError("multimesh: has no keys (m = 0)");
  const int n = vertexCount();
  const std::vector<Triangle>& tris = triangles_;
  for (int t = 0; t < triangleCount(); ++t) {
    const double kappa = stiffness(t);
    if (!std::isfinite(kappa) || kappa <= 0)
      throw InputError("multimesh: triangle " + std::to_string(t) + " has stiffness kappa = " +
                       std::to_string(kappa) + " (must be positive)");
  }
  std::set<std::pair<int, int>> edges;
  for (const auto& [a, b] : edges_) edges.insert({std::min(a, b), std::max(a, b)});
  for (int key = 0; key < keyCount(); ++key) {
    const Eigen::MatrixX2d& X = keys_[key].positions;
    if (!X.allFinite()) throw InputError("multimesh: " + keyName(key) + " has a non-finite position");
    const double size = boundingDiagonal(X);
    if (!(size > 0)) throw InputError("multimesh: " + keyName(key) + " has zero size");
    const double minArea = 1e-12 * size * size;
    for (size_t t = 0; t < tris.size(); ++t) {
      const auto& tri = tris[t];
      const double area = signedArea(X.row(tri[0]), X.row(tri[1]), X.row(tri[2]));
      if (!(area > minArea))
        throw InputError("multimesh: triangle " + std::to_string(t) + " is degenerate or inverted in " +
                         keyName(key) + " (signed area " + std::to_string(area) + ")");
    }
    const auto& pairs = keys_[key].cohesive;
    for (size_t j = 0; j < pairs.size(); ++j) {
      const CohesivePair& p = pairs[j];
      const std::string where = "multimesh: " + keyName(key) + " cohesive pair " + std::to_string(j);
      for (int v : {p.a, p.b, p.c, p.d})
        if (v < 0 || v >= n) throw InputError(where + " refers to " + vertexName(v));
      if (p.a == p.b || p.c == p.d) throw InputError(where + " has a zero-length edge");
      if (!edges.count({std::min(p.a, p.b), std::max(p.a, p.b)}) ||
          !edges.count({std::min(p.c, p.d), std::max(p.c, p.d)}))
        throw InputError(where + " names an edge that is not in the mesh");
      const double tol = 1e-6 * size;
      if ((X.row(p.a) - X.row(p.c)).norm() > tol || (X.row(p.b) - X.row(p.d)).norm() > tol)
        throw InputError(where + " is not collocated in its key (X^a != X^c or X^b != X^d)");
    }
    for (int v : keys_[key].boundary)
      if (v < 0 || v >= n) throw InputError("multimesh: " + keyName(key) + " boundary set refers to " + vertexName(v));
  }
}

}  // namespace ib
