// The block objective of Comesh Optimization's inner loop: the part of eq. 8 that depends on key
// i's positions, ODT(X_i) / area(X_i) (scaled by an ODT weight) + MIPS(X_i, X_[i+1]) +
// MIPS(X_[i-1], X_i), indices cyclic (for two keys both MIPS directions between them; for one key
// ODT alone). Units: length^2. Prepared for the many evaluations of one key's positions while
// every other key holds still.
//
// With the neighbours fixed, both MIPS terms of key i are closed forms in key i's edge matrix E
// (2 x 2, columns x1 - x0 and x2 - x0) with a per-triangle 2 x 2 symmetric matrix:
//   MIPS(X_i, X_next) = tr(adj(E)^T S adj(E)),  S = E_next^T E_next / (4 a_next)   (eq. 5)
//   MIPS(X_prev, X_i) = tr(E Q E^T) / (4 a(E)),  Q = adj(E_prev) adj(E_prev)^T
// so prepare() computes S and Q once (O(triangles)) and evaluate() reads only key i's positions,
// in flat per-triangle arrays the compiler vectorizes. comeshEnergy (comesh_energy.h) minus this
// block does not depend on X_i.
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace ib {

class BlockEnergy {
 public:
  // Prepares key i's block over `triangles` (positive in every key they are evaluated on; entries
  // with a negative corner, deleted triangles, are skipped) with the other keys as they are now.
  // odtWeight scales the ODT term (comeshEnergy's odtWeights[i]).
  void prepare(const std::vector<Triangle>& triangles, const std::vector<Eigen::MatrixX2d>& keys, int i,
               double odtWeight);

  // After a change of topology while key i's neighbours held still since prepare(): recomputes the
  // triangles whose corners changed (all of them when triangles were added or removed).
  void update(const std::vector<Triangle>& triangles, const std::vector<Eigen::MatrixX2d>& keys);

  // Threads for evaluate() on blocks of at least kParallelTriangles triangles (fewer run on one:
  // waking a thread costs more than its share). Default 1.
  void setThreads(int threads) { threads_ = std::max(1, threads); }
  static constexpr int kParallelTriangles = 8192;

  // The block energy at key i's positions x (n x 2), px^2; +infinity when a triangle is not
  // positive in x or in a neighbouring key. Writes d/dx into `gradient` (n x 2) when given.
  double evaluate(const Eigen::MatrixX2d& x, Eigen::MatrixX2d* gradient) const;

 private:
  // S, Q and the inverted flag of triangles [begin, end) from their corners and the neighbour keys.
  void prepareRange(int begin, int end, const std::vector<Eigen::MatrixX2d>& keys);

  int key_ = 0;                            // i
  int count_ = 0;                          // triangles kept
  int threads_ = 1;
  bool neighbourInverted_ = false;         // a triangle not positive in a neighbouring key
  double odtWeight_ = 1;
  std::vector<int> corner_[3];             // [corner][triangle]: vertex indices
  std::vector<double> s00_, s01_, s11_;    // S per triangle (MIPS towards the next key)
  std::vector<double> q00_, q01_, q11_;    // Q per triangle (MIPS from the previous key)
  std::vector<char> inverted_;             // per triangle: not positive in the next key
  mutable Eigen::VectorXd scratch_;        // 12 count_: edge matrices and gradient blocks
};

}  // namespace ib
