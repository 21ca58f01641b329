// Variational interpolation over a multimesh (eq. 9):
//   x(w) = argmin_x sum_i w_i [ W_C(C_i, x) + W_O(B_i, x) + W_D(X_i, x) ]  (+ the weak placement tie E_P)
// solved by an accelerated local-global method (libigl's precompute/solve split: the
// constructor does the heavy setup once, solve() is the cheap per-frame call).
//
// Iteration. The local step (rotations per triangle and key, cohesive directions and clamping,
// non-overlap targets) runs fused with the evaluation of the energy E and its gradient g. The
// global step is x <- x - H^{-1} g with H = sum_t E^T M_t(w) E + cohesive springs + mu M, an n x n
// matrix shared by x and y (global_matrix.h). With H the current frame's exact quadratic this is
// the classic global solve. H is refactorized only when w has moved by more than
// SolverOptions::refactorDistance (L1) since the last factorization. When the set of held
// cohesive pairs changes (at the start of a frame or after an accepted iteration), H is
// refactorized at the frame's weights if w has moved by more than half of refactorDistance;
// otherwise its factor is brought to the new set by rank-one updates, or, where a factorization
// costs less than those (meshes of about a hundred vertices), H is refactorized once the set has
// differed for SolverOptions::staleHeldIterations iterations or a step fails while it
// differs. Otherwise H serves as a fixed preconditioner:
// the fixed point is the same stationary point (g = 0), and the anisotropic, x-dependent
// cohesive matrix P lives in the gradient (local step), not in H. Anderson acceleration on top,
// minimizing the gradient, its history carried from frame to frame. An accelerated iterate that
// raises E is replaced by the plain step, and a plain step that raises E is backtracked, so a
// solve never returns a worse energy than its start.
//
// Threads. Internally the vertices are numbered so that each thread owns one block of them in
// every loop of an iteration (thread_layout.h); inputs and outputs use the multimesh's numbering.
// The solver's state (energies, H and its factor, Anderson's history) is behind a pointer
// (interpolator_impl.h): this header needs only Eigen and the multimesh.
//
// Units. Internally all lengths are divided by the shape size s = sqrt(mean key area), so
// lambda, tau and energies mean the same at any drawing resolution. Inputs and outputs are in
// the multimesh's own units.
#pragma once

#include "interpolation/interpolation_params.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <atomic>
#include <memory>
#include <vector>

namespace ib {

struct SolverOptions {
  double relativeTolerance = 1e-3;  // stop when |g|_inf / |g(x_start)|_inf < this (paper 7.1)
  // Near a key the solve goes on past relativeTolerance towards a tighter target, linearly in the
  // L1 distance d from w to the nearest e_i: keyTolerance at d = 0, relativeTolerance at d >=
  // keyReach, for as long as it gains (docs/solver.md, "Stopping rule"). A key frame is then the
  // drawing (at 1e-3, stylized-walk's hand, on a thin arm that costs little to swing, stayed 1.6 px
  // off its key), and the frames before it lead there without a jump. keyReach: a quarter of a
  // segment's L1 length of 2 by default. Defaults 1e-4, 0.25.
  double keyTolerance = 1e-4;
  double keyReach = 0.25;
  int maxIterations = 500;          // iteration cap; reaching it is reported as not converged
  // Anderson history length; 0 = plain local-global. Default 16: against 10, the bench sweeps
  // take 8.96 instead of 10.04 iterations per frame at 10k vertices (2 keys) and 10.7 instead of
  // 14.4 at 100k, the scenes' animations 13% fewer in all. 20 took fewer at 100k and 4 keys but
  // more on the scenes; 32 was no better.
  int andersonDepth = 16;
  double refactorDistance = 1.0;    // refactorize H when |w - w_H|_1 exceeds this; 0 = exact H every frame
  // A frame still unconverged after this many iterations with H factorized at other weights gets H
  // refactorized at its own, once: where the keys' metrics differ a lot (a tail flicking up and
  // down, drawn at 512 px) an H of w half a segment away made single frames take 600-2500
  // iterations, against 10-80 with the exact H. 0: never. Default 40.
  int slowFrameIterations = 40;
  // Where updating H's factor for changed held pairs would cost more than a
  // factorization (small meshes, or many pairs changing at once): refactorize H after this many
  // iterations in a row in which the held pairs differ from H's (a step that fails meanwhile
  // refactorizes at once); >= 1. Default 4. With 8 and 16, two bundled scenes jumped in
  // mid-animation (another minimum of the nonconvex energy); with 1, 2 and 4 they did not.
  int staleHeldIterations = 4;
  // Follow changed held pairs by rank-one updates of H's factor where they cost less
  // than a factorization and w is near H's (see above). false: refactorize by the rules above
  // only (for comparison, `inbetween bench cut`). Default true.
  bool updateFactor = true;
  double placementStiffness = 1e-5; // mu of the placement tie E_P (see placement.h), > 0
  double nonOverlapStiffness = 1;   // W_O penalty k, relative to the mean diagonal of the ARAP matrix
  // The most threads for the local step and solves; 0 = all cores. Meshes under 4000 vertices
  // always run on one; fewer than this run while other programs keep cores busy
  // (core/thread_budget.h: the thread policy). Default 0.
  int threads = 0;
  // Run fewer threads than `threads` while other work keeps cores busy (the thread budget);
  // false: always `threads` (as capped by the calling thread's OpenMP team size), to compare
  // fixed thread counts. Default true.
  bool adaptThreads = true;
};

struct InterpolationResult {
  Eigen::MatrixX2d x;                 // n x 2, the inbetween in the multimesh's units
  int iterations = 0;
  int evaluations = 0;                // local steps (energy + gradient): the start, every candidate
  double relativeResidual = 0;        // |g|_inf / |g(x_start)|_inf at the end (0 for a zero start gradient)
  double energy = 0;                  // W_I + E_P at x (normalized units)
  double startEnergy = 0;             // the same at the (aligned) start
  double interpolationEnergy = 0;     // W_I alone at x (eq. 9), without the placement tie
  bool converged = false;             // residual below tolerance, or |g| at rounding level, or at a
                                      // non-overlap contact's kink (docs/solver.md); never a small step
  bool cancelled = false;             // stopped early by the cancel flag (setCancelFlag): x is the best iterate so far
  int threads = 1;                    // threads the last iteration ran on (SolverOptions::threads, fewer
                                      // while other programs keep cores busy: core/thread_budget.h)
  int factorizations = 0;             // numeric factorizations of H during this solve
  int factorUpdates = 0;              // rank-one updates of H's factor for changed held pairs
  double factorMilliseconds = 0;      // wall time of both, part of milliseconds
  double milliseconds = 0;            // wall time of this solve, factorization included
  std::vector<double> energyHistory;    // energy after each iteration (start first)
  std::vector<double> residualHistory;  // relative residual after each iteration (start first: 1)
  // Per cohesive pair, in the multimesh's order (key 0's pairs C_0, then C_1, ...), at the last
  // iterate: 1 while the pair holds (l/3 d < tau, eq. 11), 0 once it is clamped (let go) or its
  // key has zero weight.
  std::vector<char> heldPairs;
};

// Extra per-vertex springs E_S = 1/2 sum_v c_v |x_v - y_v|^2 added to the energy of one solve:
// the dynamics terms (W_T of eq. 18 and the anchor, see dynamics.h). They also hold the rigid
// motions the other energies leave free, so a solve with springs does not place groups rigidly
// on the blend; every group needs some c_v > 0.
struct VertexSprings {
  Eigen::VectorXd stiffness;  // n x 1, c_v >= 0 in normalized units (energy per shape size squared)
  Eigen::MatrixX2d target;    // n x 2, y_v in the multimesh's units
};

struct EnergyEvaluation {
  double energy = 0;          // W_I + E_P, normalized units
  Eigen::MatrixX2d gradient;  // d energy / d x, n x 2, with x in the multimesh's units
};

class Interpolator {
 public:
  // Validates the multimesh and the parameters (InputError naming the field on failure).
  Interpolator(const Multimesh& mesh, const InterpolationParams& params, const SolverOptions& options);
  ~Interpolator();
  Interpolator(Interpolator&&) noexcept;
  Interpolator& operator=(Interpolator&&) noexcept;

  // Solves for weights w (m x 1, convex; validateWeights). warmStart (n x 2, multimesh units) is the previous
  // frame; without it the solve starts from the linear blend sum_i w_i X_i. springs, when given,
  // add E_S to this solve's energy (and to H, which is then refactorized whenever some c_v has
  // moved by more than a fifth since the last factorization). Wrong sizes and non-finite inputs
  // are the caller's error (std::invalid_argument).
  InterpolationResult solve(const Eigen::VectorXd& w, const Eigen::MatrixX2d* warmStart = nullptr,
                            const VertexSprings* springs = nullptr);

  // Forgets what carries over from frame to frame (the Anderson history, the factorization of H
  // and, under CutTiming::kTau, which pairs let go), so the next solve behaves exactly as on a fresh Interpolator: a stream restarted from its
  // first frame repeats its frames bit for bit.
  void forgetHistory();

  // Live changes for the next solves (a player's sliders), validated as the constructor validates
  // (nothing changes when they throw). Neither rebuilds the thread layout, the vertex orderings
  // or H's sparsity pattern (W_O's entries stay in the pattern, zero while it is off); both
  // forget the history (as forgetHistory), so H is factorized afresh at the next solve and that
  // solve gives a fresh Interpolator's result with these values, bit for bit.
  // lambda, tau, alpha and non-overlap (InputError naming the field).
  void setParameters(const InterpolationParams& params);
  // Per-triangle stiffness kappa (t x 1, the multimesh's triangle order): std::invalid_argument
  // for a wrong size, InputError for a value that is not a finite number > 0. The stiffness scale
  // (stiffnessScale()) and what is stated relative to it follow.
  void setStiffness(const Eigen::VectorXd& kappa);
  // While *flag is true, solve() stops within one iteration and returns the best iterate so far
  // with cancelled = true (finite, never NaN). Another thread may set it at any time; the caller
  // clears it. nullptr (the default): never cancelled. The flag must outlive the solves.
  void setCancelFlag(const std::atomic<bool>* flag);

  // Energy and gradient at x for weights w, local-step quantities taken at x (for tests).
  EnergyEvaluation evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const;

  // Boundary vertices of the active keys inside the deformed mesh at x (0 when W_O holds),
  // counted whether or not W_O is enforced.
  int countOverlaps(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const;

  double shapeSize() const;  // s = sqrt(mean key area), in the multimesh's units
  // Mean diagonal entry of the ARAP matrix at uniform weights (normalized units): how stiff one
  // vertex is held by its triangles. Spring constants are stated relative to it.
  double stiffnessScale() const;
  int keyCount() const;
  int vertexCount() const;
  int threads() const;         // threads the solve runs on
  int triangleCount() const;
  long factorNonZeros() const;  // non-zeros of H's Cholesky factor

  class Impl;  // interpolator_impl.h: the solver's state, for the solver's own files

 private:
  std::unique_ptr<Impl> impl_;
};

// Checks interpolation weights: m entries, finite, non-negative, summing to 1 (within 1e-6);
// throws std::invalid_argument otherwise (weights come from a timeline or a front end that
// normalized them, never straight from a file).
void validateWeights(const Eigen::VectorXd& w, int keyCount);

// Checks lambda, tau and alpha as the Interpolator does (InputError naming the field).
void validateInterpolationParams(const InterpolationParams& params);

// Checks per-triangle stiffness as Interpolator::setStiffness does: t entries
// (std::invalid_argument otherwise), each a finite number > 0 (InputError naming the entry).
void validateStiffness(const Eigen::VectorXd& kappa, int triangleCount);

}  // namespace ib
