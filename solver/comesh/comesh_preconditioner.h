// A Sobolev preconditioner for Comesh Optimization's gradient steps: descent directions
// d = -(L + s I)^-1 g on the interior vertices, L the graph Laplacian of the shared topology with
// the boundary held (Dirichlet), s = `shift`. Plain gradient descent on MIPS and ODT moves the
// mesh's smooth, mesh-wide modes very slowly; through L^-1 they move at the pace of the local ones
// (modes of L below s are left as they are, so a smaller s smooths more). L depends on
// topology only, so it is shared by every key. Any such L is a valid preconditioner, so after
// flips alone it is kept for a while (refactorized every `refreshAfter` calls); after splits or
// collapses, which change the vertex set, it is rebuilt at once. Every rebuild orders the
// unknowns anew with approximate minimum degree (AMD), which is cheap, instead of METIS. For the
// same reason the factor need not be exact: its small entries are dropped (`dropTolerance`).
#pragma once

#include "comesh/comesh_mesh.h"
#include "linalg/cholesky_preconditioner.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

class SobolevPreconditioner {
 public:
  explicit SobolevPreconditioner(int threads) : threads_(threads) {}

  // Rebuilds L for `mesh` when its vertex set changed, or its edges changed and L is older than
  // `refreshAfter` calls.
  void update(const ComeshMesh& mesh);

  // Calls between refactorizations while only flips happen. A refactorization costs about 0.1 s
  // at 17k vertices; 400 instead of 100 took 3234 instead of 3477 inner iterations there and
  // changed the small cases by no more than their run-to-run spread. Default 400.
  int refreshAfter = 400;
  // s above, relative to L's unit edge weights. Measured on bench comesh: 0.3 takes fewer inner
  // iterations than 1 on every case (17k vertices: 3856 instead of 4604). Default 0.3.
  double shift = 0.3;
  // Entries of L's Cholesky factor below this, relative to their diagonals, are dropped
  // (CholeskyPreconditioner::setDropTolerance): at 17k vertices 1e-3 keeps 45% of them, the
  // solves match the exact ones within about 1%, and an inner iteration costs 9% less; over square
  // to hexagon at 15k-19k vertices the inner iterations went from 13,432 to 12,827 at the same
  // eq. 8 (within 0.02%). Default 1e-3.
  double dropTolerance = 1e-3;

  // direction (n x 2) = -(L + s I)^-1 gradient on interior vertices, -gradient / (valence + 1) on
  // the others (about the local scale of the same operator).
  void apply(const ComeshMesh& mesh, const Eigen::MatrixX2d& gradient, Eigen::MatrixX2d& direction) const;

 private:
  long version_ = -1, vertexSetVersion_ = -1;  // the mesh's versions when L was built
  int age_ = 0;                                 // update() calls since
  std::vector<int> unknown_;  // [vertex]: row in L, or -1 (boundary, fixed, or without triangles)
  std::vector<int> valence_;  // [vertex]
  int threads_;                       // for the solves
  CholeskyPreconditioner factor_{1};  // of L + s I; ordered and analysed anew with every rebuild
  int unknowns_ = 0;                  // rows of L
};

}  // namespace ib
