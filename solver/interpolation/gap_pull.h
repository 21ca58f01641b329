// W_G, the pull of a cut's two sides towards the gap the keys where it is open draw between them
// (../shared/topology-change.md, lever 1; docs/solver.md, "Cut timing"). For every cohesive pair
// (a, b | c, d) and every key j where the pair is open (not among that key's cohesive pairs):
//   w_j (1 - r) l/3 lambda Q(u - R_j U_j, v - R_j V_j),   Q(p, q) = |p|^2 + p.q + |q|^2,
//   u = x^a - x^c, v = x^b - x^d,  U_j, V_j the same differences in key j,
// r = releaseRamp of the open keys' total weight (cohesive_energy.h; no pull under CutTiming::kTau),
// R_j the rotation of the cut's neighbourhood from key j: the closest rotation to
// F = D_s(x) D_s(X_j)^{-1} + D_t(x) D_t(X_j)^{-1} for a triangle s at a and a triangle t at c, taken
// at the start of each frame's solve (freezeRotations) and held through it, so that within a frame
// the pull is a quadratic whose Hessian H holds exactly: Q is the form of the cohesive spring at
// alpha = 1/2, and the pull joins the pair's spring in the global matrix. (With R following x
// within the solve, its exact gradient left the local-global iteration stalled at a relative
// residual of 5e-3 after 500 iterations on glued squares; frozen per frame, 10-30.) The closed
// keys pull u, v to zero (W_C), the open keys to their drawn gap: the gap of an inbetween blends the
// two, where before nothing wanted the sides apart and they parted in one frame.
#pragma once

#include "interpolation/cohesive_energy.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

class GapPull {
 public:
  // keys: X_i (n x 2 each, normalized units), the cohesive terms' keys. One pull per distinct pair
  // that some key leaves open.
  GapPull(const Multimesh& mesh, const std::vector<Eigen::MatrixX2d>& keys, const CohesiveEnergy& cohesive,
          const CohesiveParams& params);

  void setParams(const CohesiveParams& params) { params_ = params; }
  bool empty() const { return pulls_.empty(); }

  // Takes R_j for every pull and open key from x (n x 2): at the start of a frame's solve.
  void freezeRotations(const Eigen::MatrixX2d& x);

  // Returns W_G at x with weights w and the frozen rotations, and adds its gradient (n x 2).
  double evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, Eigen::MatrixX2d& gradient) const;

  // The isotropic spring constant of pull p's pair at weights w (sum over its open keys of
  // w_j (1 - r) l/3 lambda), for the global matrix; pair(p) its vertices.
  double springConstant(int p, const Eigen::VectorXd& w) const;
  const CohesivePair& pair(int p) const { return pulls_[p].pair; }
  int size() const { return static_cast<int>(pulls_.size()); }

 private:
  struct Pull;
  // The pull's share at w: its open keys' total weight through 1 - releaseRamp; 0 under kTau.
  double share(const Pull& pull, const Eigen::VectorXd& w) const;

  struct Pull {
    CohesivePair pair;
    double restLength = 0;  // l, as the cohesive term's
    Triangle at, ac;        // a triangle at vertex a and one at vertex c
    // Per open key: its index, U_j, V_j, and D(X_j)^{-1} of the two triangles.
    std::vector<int> key;
    std::vector<Eigen::Vector2d> U, V;
    std::vector<Eigen::Matrix2d> Ma, Mc;
    std::vector<Eigen::Matrix2d> R;  // frozen rotations (identity until freezeRotations)
  };
  CohesiveParams params_;
  std::vector<Pull> pulls_;
};

}  // namespace ib
