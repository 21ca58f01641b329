// The interpolation solver's state and steps, behind Interpolator's pointer (interpolator.h
// says what they compute). For the solver's own files: interpolator.cpp (the iteration) and
// interpolator_factor.cpp (when H is refactorized or updated).
#pragma once

#include "core/thread_block.h"
#include "core/thread_budget.h"
#include "interpolation/cohesive_energy.h"
#include "interpolation/gap_pull.h"
#include "interpolation/deformation_energy.h"
#include "interpolation/global_matrix.h"
#include "interpolation/interpolator.h"
#include "interpolation/non_overlap.h"
#include "interpolation/placement.h"
#include "interpolation/thread_layout.h"
#include "linalg/anderson.h"

#include <Eigen/Core>
#include <atomic>
#include <memory>
#include <utility>
#include <vector>

namespace ib {

class Interpolator::Impl {
 public:
  Impl(const Multimesh& mesh, const InterpolationParams& params, const SolverOptions& options);

  InterpolationResult solve(const Eigen::VectorXd& w, const Eigen::MatrixX2d* warmStart, const VertexSprings* springs);

  void forgetHistory();
  void setParameters(const InterpolationParams& params);
  void setStiffness(const Eigen::VectorXd& kappa);
  void setCancelFlag(const std::atomic<bool>* flag) { cancel_ = flag; }

  EnergyEvaluation evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const;

  int countOverlaps(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const;

  double shapeSize() const { return scale_; }
  double stiffnessScale() const { return stiffnessScale_; }
  int keyCount() const { return static_cast<int>(keys_.size()); }
  int vertexCount() const { return static_cast<int>(keys_.front().rows()); }
  int threads() const { return vertexSplit_.threads(); }
  int triangleCount() const { return deformation_->triangleCount(); }
  long factorNonZeros() const { return global_->factor().factorNonZeros(); }

 private:
  struct Frame;
  struct State;
  Impl(ThreadLayout layout, const InterpolationParams& params, const SolverOptions& options);
  double gradientNorm(const Eigen::MatrixX2d& g) const;  // |g|_inf, over the vertex split
  // The stiffness scale from the current kappa, and what is stated relative to it: the gradient
  // floor and the W_O penalty (constructor and setStiffness).
  void updateStiffnessScale();
  GlobalMatrixSources matrixSources() const;  // what H is built from, with the current parameters
  void updatePlacementWeights();  // placementWeight_ and placementTie_ for params_.placement
  bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
  Frame makeFrame(const Eigen::VectorXd& w, const VertexSprings* springs) const;
  void evaluateState(const Frame& frame, State& state) const;
  // std::invalid_argument unless CohesiveParams::perTerm is empty or one per cohesive term.
  void checkCutTimings(const InterpolationParams& params) const;
  // Only what placement groups need: held pairs and non-overlap contacts.
  void evaluateLinks(const Frame& frame, State& state) const;
  void align(const Frame& frame, const State& reference, Eigen::MatrixX2d& x);
  // W_G with its anchors turned with their groups (gap_pull.h, GroupAngles), added to s.
  void addGapPull(const Frame& frame, State& s) const;
  // One safeguarded iteration from s: the Anderson candidate, else the plain step, else (if the
  // set of held pairs changed) a refactorization to retry with, else a backtracked plain
  // step. On kAccepted the new iterate is in candidate; plain is scratch.
  enum class Step { kAccepted, kRefactorized, kStalled };
  double toleranceAt(const Eigen::VectorXd& w) const;  // SolverOptions::keyTolerance near a key
  bool contactSteps_ = true;  // step() may take an uphill plain step at a contact (solve() says when)
  Step step(const Frame& frame, const State& s, State& candidate, Eigen::MatrixX2d& plain, InterpolationResult& result);
  // H's factor for a frame's weights w (m x 1), vertex springs (n x 1 or empty) and held
  // cohesive pairs (interpolator_factor.cpp); all counted and timed in result.
  // Factorizes H, unless the factor still models the frame (ensureFactorization: only the pairs
  // differing is followed as in followHeld), or always (refactorize).
  void ensureFactorization(const Eigen::VectorXd& w, const Eigen::VectorXd& springs, const std::vector<char>& held,
                           InterpolationResult& result);
  void refactorize(const Eigen::VectorXd& w, const Eigen::VectorXd& springs, const std::vector<char>& held,
                   InterpolationResult& result);
  // Brings the factor to changed held pairs: refactorized at w when w has moved by more than
  // half of refactorDistance since H was built (a factor change due anyway catches up with the
  // weights), else by rank-one updates (GlobalMatrix::updateHeld) unless they would cost more
  // than a factorization. Returns whether the factor changed.
  bool followHeld(const Eigen::VectorXd& w, const Eigen::VectorXd& springs, const std::vector<char>& held,
                    InterpolationResult& result);
  // The rank-one branch of followHeld: false, nothing done, when too costly or turned off.
  bool updateFactorization(const std::vector<char>& held, InterpolationResult& result);

  InterpolationParams params_;
  SolverOptions options_;
  // Internally, vertices are numbered as threadLayout() numbers them (see thread_layout.h), and
  // thread p works on the vertices [vertexSplit_.begin(p), vertexSplit_.end(p)) in every loop.
  std::vector<int> originalOf_;            // internal vertex k is the caller's vertex originalOf_[k]
  std::vector<int> triangleOriginalOf_;    // internal triangle k is the caller's triangle triangleOriginalOf_[k]
  RowSplit vertexSplit_, triangleSplit_;
  double scale_ = 1;                       // shape size s
  std::vector<Eigen::MatrixX2d> keys_;     // X_i / s
  double vertexWeight_ = 0;                // placement weight m_v = 1/n of every vertex (placement.h)
  Eigen::VectorXd placementWeight_;        // Placement::kStill's m_v per vertex; empty: vertexWeight_
  Eigen::VectorXd placementTie_;           // mu m_v per vertex with placementWeight_; empty: none
  std::unique_ptr<DeformationEnergy> deformation_;
  std::unique_ptr<CohesiveEnergy> cohesive_;
  std::unique_ptr<GapPull> gapPull_;  // the open keys' pull on the cuts (CutTiming::kRelease)
  std::unique_ptr<NonOverlap> nonOverlap_;  // always built; used when params_.nonOverlap
  PlacementGroups groups_;
  std::vector<std::pair<int, int>> groupLinks_;  // the links groups_ was last built from
  std::unique_ptr<GlobalMatrix> global_;   // H and its factor; built from the energies above
  AndersonAcceleration anderson_;          // history kept across frames
  ThreadBudget budget_;                    // how many of the layout's threads to run now
  double gradientFloor_ = 0;               // absolute |g|_inf below which a start is converged
  double stiffnessScale_ = 0;              // see stiffnessScale()
  const std::atomic<bool>* cancel_ = nullptr;  // setCancelFlag; null: never cancelled
};

// One frame's fixed data, normalized by the shape size s (n vertices, m keys).
struct Interpolator::Impl::Frame {
  Eigen::VectorXd w;
  Eigen::VectorXd springs;         // c_v (empty: no springs)
  Eigen::MatrixX2d springTarget;   // y_v, normalized
  ActiveKeys keys;
  Eigen::MatrixX2d blend;         // Xbar(w) = sum_i w_i X_i, normalized
  std::vector<int> participants;  // W_O boundary vertices
};

struct Interpolator::Impl::State {
  Eigen::MatrixX2d x, gradient;
  double energy = 0;                          // W_I + E_P
  double placement = 0;                       // E_P alone
  std::vector<char> held;                   // cohesive terms not clamped
  std::vector<std::pair<int, int>> contacts;  // W_O offenders
};

}  // namespace ib
