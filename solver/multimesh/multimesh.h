// Multimesh (paper section 3.2): one shared triangle topology O = {V, E, T} on OpenMesh with,
// for every key shape i in [0, m): vertex positions X_i (n x 2), cohesive edge pairs C_i and the
// boundary vertex set B_i; plus a stiffness kappa per triangle.
//
// Conventions: vertices and triangles are numbered 0..n-1 and 0..t-1 in the order they were given.
// Every triangle has positive signed area (x1-x0) x (x2-x0) in every key, in the units the
// positions are given in (drawing pixels for scenes; any unit for meshes built in code). The
// topology never changes after construction: its edges and boundary are derived once (with
// OpenMesh, which checks that it is manifold), and the header shows none of OpenMesh.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace ib {

// A cohesive edge pair C_i^j = {{a, b}, {c, d}} (eq. 10): mesh edges (a, b) and (c, d) that
// are collocated in the key that owns the pair, with X^a == X^c and X^b == X^d there.
struct CohesivePair {
  int a = 0, b = 0, c = 0, d = 0;
};

using Triangle = std::array<int, 3>;
using Edge = std::array<int, 2>;

class Multimesh {
 public:
  // Shared topology from a triangle list over vertices 0..vertexCount-1. Throws InputError on
  // out-of-range or repeated indices and on faces that make it non-manifold or inconsistently
  // oriented (a multimesh file can hold any of these).
  Multimesh(int vertexCount, const std::vector<Triangle>& triangles);

  int vertexCount() const { return vertexCount_; }
  int triangleCount() const { return static_cast<int>(triangles_.size()); }
  int keyCount() const { return static_cast<int>(keys_.size()); }

  // Triangles as vertex index triples (t x 3), in the order given.
  const std::vector<Triangle>& triangles() const { return triangles_; }
  // Every edge of the topology once, {v0, v1}.
  const std::vector<Edge>& edges() const { return edges_; }
  // The edges with one triangle, each {from, to} as that triangle runs along it: with triangles
  // of positive area, the shape lies to the left of each.
  const std::vector<Edge>& boundaryEdges() const { return boundaryEdges_; }
  // [vertex]: 1 where the vertex lies on the topology's boundary (the shape's outline and every
  // side of every cut), else 0. B_i, the boundary set of a key, is boundaryVertices(i).
  const std::vector<char>& onBoundary() const { return onBoundary_; }
  // The boundary as closed loops of vertices, each in boundaryEdges' direction.
  std::vector<std::vector<int>> boundaryLoops() const;

  // Appends key i = keyCount(): positions X_i (n x 2), cohesive pairs C_i, boundary set B_i.
  // Sizes are checked here (std::invalid_argument); geometry is checked by validate().
  int addKey(const Eigen::MatrixX2d& positions, std::vector<CohesivePair> cohesive,
             std::vector<int> boundary);

  const Eigen::MatrixX2d& keyPositions(int key) const { return keys_.at(key).positions; }  // X_i, n x 2
  void setKeyPositions(int key, const Eigen::MatrixX2d& positions);
  const std::vector<CohesivePair>& cohesivePairs(int key) const { return keys_.at(key).cohesive; }
  const std::vector<int>& boundaryVertices(int key) const { return keys_.at(key).boundary; }

  // Per-triangle stiffness kappa_k (eq. 16), default 1.
  double stiffness(int triangle) const { return kappa_.at(triangle); }
  void setStiffness(int triangle, double kappa);
  Eigen::VectorXd stiffnesses() const;  // t x 1

  // Checks everything the solver relies on and throws InputError naming the key, triangle,
  // vertex or pair at fault: at least one key, finite positions, positive triangle areas in
  // every key (relative to the key's size), positive finite kappa, valid cohesive pairs whose
  // edges exist and are collocated in their key, valid boundary indices.
  void validate() const;

 private:
  struct Key {
    Eigen::MatrixX2d positions;  // n x 2
    std::vector<CohesivePair> cohesive;
    std::vector<int> boundary;
  };
  int vertexCount_ = 0;
  std::vector<Triangle> triangles_;
  std::vector<Edge> edges_, boundaryEdges_;
  std::vector<char> onBoundary_;
  std::vector<double> kappa_;  // [triangle]
  std::vector<Key> keys_;
};

// The same multimesh with its vertices renumbered: vertex k is the old vertex vertexOrder[k] (a
// permutation of 0..n-1). Positions, triangles, cohesive pairs and boundary sets follow; the
// triangles keep their order (and so does OpenMesh's construction, which can depend on it).
Multimesh renumbered(const Multimesh& mesh, const std::vector<int>& vertexOrder);

// Edge matrix [x1 - x0, x2 - x0] of triangle `tri` in positions x (n x 2): 2 x 2, columns are edges.
Eigen::Matrix2d edgeMatrix(const Eigen::MatrixX2d& x, const Triangle& tri);

// Signed area of triangle (p0, p1, p2): positive when counter-clockwise in a y-up frame.
double signedArea(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2);

// Size of a point set: the diagonal of its bounding box (0 for fewer than two points).
double boundingDiagonal(const Eigen::MatrixX2d& points);

}  // namespace ib
