// W_O, the non-overlap term of eqs. (14)-(15): a boundary vertex of B_i must not lie in the
// interior of the deformed mesh (the cover of its triangles, boundary edges excluded).
//
// Inside the solver the indicator is enforced as in the paper's local step: a boundary vertex
// found inside a triangle not incident to it is given the nearest feasible point p_j (the
// closest point on a mesh boundary edge not incident to it that no other triangle covers) and pulled there by a stiff
// penalty (k/2) |x_j - p_j|^2, whose gradient pushes x_j out and the edge's endpoints back (the
// equal and opposite contact force). After the solve, project() moves remaining offenders to
// their p_j, repeating while any remain, so the returned frame has no boundary vertex inside.
#pragma once

#include "core/box_grid.h"
#include "interpolation/deformation_energy.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

namespace ib {

class NonOverlap {
 public:
  // stiffness: the penalty constant k (energy per squared length, normalized units).
  NonOverlap(const Multimesh& mesh, double stiffness);

  // Union of B_i over the active keys, sorted.
  std::vector<int> participants(const ActiveKeys& keys) const;
  // Every vertex in some B_i (for the preconditioner).
  const std::vector<int>& allBoundaryVertices() const { return allBoundary_; }
  double stiffness() const { return stiffness_; }
  void setStiffness(double stiffness) { stiffness_ = stiffness; }  // the penalty constant k

  // Penalty energy; adds its gradient to gradient (n x 2). contacts receives (boundary vertex,
  // a vertex of the triangle it is inside) for every offender.
  double evaluate(const Eigen::MatrixX2d& x, const std::vector<int>& participants, Eigen::MatrixX2d& gradient,
                  std::vector<std::pair<int, int>>& contacts) const;

  // Moves offenders to their nearest feasible points, repeating (at most `passes` times) while
  // moves create new ones; returns how many offenders remain.
  int project(Eigen::MatrixX2d& x, const std::vector<int>& participants, int passes = 20) const;

  // Number of participants strictly inside a triangle not incident to them.
  int countInside(const Eigen::MatrixX2d& x, const std::vector<int>& participants) const;

 private:
  struct Offender {
    int vertex = -1;
    int triangle = -1;       // a triangle it is inside
    Eigen::Vector2d target;  // nearest feasible point p_j = (1 - t) x_a + t x_b
    int edgeA = -1, edgeB = -1;
    double t = 0;
  };
  struct Grids {
    BoxGrid triangles;  // deformed triangles' boxes
    BoxGrid edges;      // deformed boundary edges' boxes
  };
  Grids buildGrids(const Eigen::MatrixX2d& x) const;
  // Whether vertex v lies inside a triangle not incident to it; fills o (without a target).
  bool detect(const Eigen::MatrixX2d& x, const Grids& grids, int v, Offender& o) const;
  // A triangle not incident to vertex v (nor its cohesive partners) whose interior holds q, or -1.
  int coveringTriangle(const Eigen::MatrixX2d& x, const Grids& grids, const Eigen::Vector2d& q, int v) const;
  // Nearest feasible point for o (edgeA stays -1 if there is none).
  void findTarget(const Eigen::MatrixX2d& x, const Grids& grids, Offender& o) const;
  std::vector<Offender> offenders(const Eigen::MatrixX2d& x, const std::vector<int>& participants, bool withTargets) const;
  std::vector<Offender> offenders(const Eigen::MatrixX2d& x, const Grids& grids, const std::vector<int>& participants,
                                  bool withTargets) const;
  bool excluded(int vertex, int other) const;  // other is vertex itself or a cohesive partner
  // p in the interior of the mesh through triangle k: inside the closed triangle, and not on a
  // mesh boundary edge or boundary vertex (interior edges and vertices are interior).
  bool interiorPoint(const Eigen::Vector2d& p, const Eigen::MatrixX2d& x, int k) const;

  std::vector<Triangle> triangles_;
  std::vector<std::pair<int, int>> boundaryEdges_;  // topological boundary of the shared mesh
  std::vector<std::vector<int>> keyBoundary_;       // B_i, sorted
  std::vector<int> allBoundary_;
  std::vector<std::vector<int>> partners_;          // vertices collocated with v by a cohesive pair
  std::vector<std::array<char, 3>> boundaryEdge_;   // per triangle: edge opposite corner c is boundary
  std::vector<char> boundaryVertex_;
  double stiffness_;
};

}  // namespace ib
