// H, the matrix of the interpolation solver's global step x <- x - H^{-1} g (n x n, shared by the
// x and y columns, lower triangle stored):
//   H = sum_t E^T M_t(w) E                      ARAP with rotations frozen (deformation_energy.h)
//     + sum_j k_j S_j [[2,1],[1,2]] S_j^T        isotropic springs of the held pairs
//     + (mu m_v + c_v) I                         placement tie and per-vertex springs
//     + k_O on every boundary vertex             when W_O is enforced (else 0 there, same pattern)
// Assembled into a pattern recorded once (fixed_pattern.h) and factorized. The factor serves as
// a fixed preconditioner while the frame stays close to the one it was built for (models()), so
// a frame usually costs no factorization at all.
#pragma once

#include "interpolation/cohesive_energy.h"
#include "interpolation/gap_pull.h"
#include "interpolation/deformation_energy.h"
#include "interpolation/non_overlap.h"
#include "linalg/cholesky_preconditioner.h"
#include "linalg/fixed_pattern.h"

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <vector>

namespace ib {

// What H is built from. The energies stay owned by the caller and must outlive the GlobalMatrix.
struct GlobalMatrixSources {
  const DeformationEnergy* deformation = nullptr;
  const CohesiveEnergy* cohesive = nullptr;
  const NonOverlap* nonOverlap = nullptr;  // null: W_O not enforced, no boundary springs
  double tie = 0;                          // mu m_v, the placement tie on every vertex's diagonal
  double stiffnessScale = 1;               // one vertex's stiffness; c_v off H's by under 2% of it still match
  // With nonOverlap given: whether W_O is enforced. false keeps the boundary entries in H's
  // pattern with value 0, so W_O can be switched on and off without a new pattern.
  bool enforceNonOverlap = true;
  const GapPull* gapPull = nullptr;  // the open keys' pull on the cuts' springs; null: none
  const Eigen::VectorXd* ties = nullptr;  // mu m_v per vertex (n x 1) instead of tie; null: tie
};

// The frame H is wanted for.
struct GlobalMatrixFrame {
  const Eigen::VectorXd& w;         // m x 1 weights
  const Eigen::VectorXd& springs;   // n x 1 vertex springs c_v (empty: none)
  const std::vector<char>& held;  // per cohesive term: not clamped
};

class GlobalMatrix {
 public:
  // partStart: the thread layout's elimination plan (H arrives in its order, see
  // CholeskyPreconditioner::setPreordered), one entry more than threads.
  GlobalMatrix(GlobalMatrixSources sources, int vertices, std::vector<int> partStart, int threads);

  // Whether the factor still models the frame: factorized, built with the same held cohesive
  // pairs, w within refactorDistance (L1; 0: exactly the same w) and every c_v within a fifth.
  bool models(const GlobalMatrixFrame& frame, double refactorDistance) const;
  // Assembles and factorizes H for the frame. Throws std::runtime_error if H is not positive
  // definite.
  void factorize(const GlobalMatrixFrame& frame);
  // Brings the factor to the held pairs `held` (one entry per term) without
  // refactorizing: two rank-one modifications per pair that engaged or let go, with its spring at
  // the weights H was built for, so H stays what factorize() builds for those weights and pairs.
  // Needs a factor (std::logic_error otherwise). Returns false if it had to factorize instead
  // (a downdate that lost definiteness to rounding).
  bool updateHeld(const std::vector<char>& held);
  // Multiply-adds updateHeld(held) would take, comparable with factorizationCost().
  long updateCost(const std::vector<char>& held) const;
  // Multiply-adds of a factorization (CholeskyPreconditioner::factorizationCost).
  long factorizationCost() const { return factor_.factorizationCost(); }
  // Forgets the factor: the next models() is false.
  void invalidate() { valid_ = false; }
  // New values for what H is built from (the parameters, stiffness and whether W_O is enforced)
  // with the same energies, so H keeps its pattern; forgets the factor. std::logic_error if an
  // energy differs from the constructor's.
  void setSources(const GlobalMatrixSources& sources);

  const CholeskyPreconditioner& factor() const { return factor_; }
  // The held pairs the factor was built with.
  const std::vector<char>& held() const { return held_; }

 private:
  bool rampsMatch(const Eigen::VectorXd& w) const;  // every cut's release ramp within 0.1 of H's
  const Eigen::SparseMatrix<double>& assemble(const GlobalMatrixFrame& frame);
  bool springsMatch(const Eigen::VectorXd& springs) const;

  GlobalMatrixSources sources_;
  int vertices_ = 0;
  FixedPatternAssembly assembly_;  // H's entries, in the same order at every factorization
  CholeskyPreconditioner factor_;
  bool valid_ = false;             // factor_ holds H for weights_, springs_ and held_
  Eigen::VectorXd weights_;
  Eigen::VectorXd springs_;
  std::vector<char> held_;
};

}  // namespace ib
