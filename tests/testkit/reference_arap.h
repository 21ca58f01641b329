// A yardstick for benchmarks: single-key 2D ARAP deformation (local-global, one rotation per
// triangle, cotangent weights) in libigl's formulation, serial. The interpolation speed targets
// are stated beside libigl's figures on this kind of machine (3.0 ms per iteration at 10k
// vertices, 49 ms at 100k; docs/benchmarks.md); timing this next to the interpolator tells how fast the shared
// machine ran during a benchmark, so that figures from different runs can be compared.
//
// Energy: E(x) = sum_t min_{R_t in SO(2)} sum_{edges e=(i,j) of t} c_e |(x_i - x_j) - R_t (X_i - X_j)|^2,
// with c_e half the cotangent of the angle opposite e in the rest triangle, and the handle
// vertices pinned. Per iteration, as libigl's arap_solve does it:
//   S = CSM * [x; x]   (CSM: 2t x 2n sparse, covariance scatter; S: 2t x 2, row d*t + k is
//                       row d of triangle k's covariance sum_e c_e X_e x_e^T)
//   R_k = polar(S_k)   (one 2 x 2 SVD per triangle)
//   b = K * vec(R)     (K: 2n x 4t sparse; b: 2n, right-hand side per coordinate)
//   L_ff x_f = b_f - L_fc x_c, one prefactored sparse Cholesky solve per coordinate.
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

namespace ib {

class ReferenceArap {
 public:
  // rest: n x 2 positions; triangles counter-clockwise with positive area; handles: pinned
  // vertices, at least one. Throws InputError on degenerate triangles, bad indices or no handles.
  // Does the heavy set-up once: operators, the free-vertex system and its factorization.
  ReferenceArap(const Eigen::MatrixX2d& rest, const std::vector<Triangle>& triangles, const std::vector<int>& handles);

  // One local-global iteration: x (n x 2) is updated in place, its handle rows set to
  // handlePositions (h x 2, in the order the handles were given). E(x) never increases.
  void iterate(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& handlePositions) const;

  // E(x) above, with each R_t the best rotation for x.
  double energy(const Eigen::MatrixX2d& x) const;

 private:
  Eigen::VectorXd rotationsColumn(const Eigen::MatrixX2d& x) const;  // vec(R): 4t, entry (2a+b)*t + k = R_k(a, b)

  int n_ = 0, t_ = 0;
  std::vector<Triangle> triangles_;
  Eigen::MatrixX2d rest_;
  std::vector<Eigen::Vector3d> cot_;           // per triangle: c_e for edges (1,2), (2,0), (0,1)
  Eigen::SparseMatrix<double> csm_;            // 2t x 2n
  Eigen::SparseMatrix<double> k_;              // 2n x 4t
  std::vector<int> handles_, free_;            // pinned and free vertices
  Eigen::SparseMatrix<double> lff_, lfc_;      // L restricted to free x free and free x pinned
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt_;
};

}  // namespace ib
