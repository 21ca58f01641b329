// W_G, the pull of a cut's two sides towards the gap the keys where it is open draw between them,
// while the cut lets go (../shared/topology-change.md, lever 1; docs/solver.md, "Cut timing"). For
// every cohesive pair (a, b | c, d) and every key j where the pair is open:
//   w_j (1 - r) f / o  l/3 lambda  [Q(u - o R_j U_j, v - o R_j V_j) + gamma_j |R_j - B_j|_F^2],
//   Q(p, q) = |p|^2 + p.q + |q|^2,  u = x^a - x^c, v = x^b - x^d,  U_j, V_j the same in key j,
// o the open keys' total weight, r = releaseRamp(o) and f = pullFade(o) (cohesive_energy.h; no
// pull under CutTiming::kTau, at o = 0 or at o = 1). The closing keys pull the gap to zero with
// weight r, the open keys to o times their drawn gap with 1 - r: the gap grows over the window
// to where the blend of the keys puts the pieces, and the pull fades out after it, so the pieces
// are free again (as the paper has them) without a jump.
// R_j, one per cut (its pairs end to end) and open key, is the rotation that minimizes the cut's
// brackets (a local step, as ARAP's rotations: the gradient is the brackets' at fixed R_j), so Q
// turns with the pieces and the cut's gap turns as one (one rotation per pair tore the edges of
// cell-splitting's cells apart). B_j, the rotation of the cut's neighbourhood in the frame's blend
// of the keys relative to key j (freezeRotations, once per frame) turned by the angle its
// placement group stands from the blend (GroupAngles), anchors it while the sides are shut and u,
// v say nothing of a direction: gamma_j = 0.01 o^2 (|U_j|^2 + |V_j|^2). Turned with the group,
// W_G is invariant under the group's turn, as placement (which turns groups by E_P alone)
// requires; with B_j frozen in the world, the solves crawled or stalled (continental-drift 41 of
// 121 frames converged) and a placement minimizing E_P and the anchor together jumped where the
// pull ends (chomp 27x on its last frame). Q is the cohesive spring's form at alpha = 1/2, so the
// pull joins the pair's spring in the global matrix.
#pragma once

#include "interpolation/cohesive_energy.h"
#include "interpolation/placement.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

// Per placement group, the angle (rad) by which the group stands turned from the frame's blend
// (its Procrustes angle): the anchors turn with it, so W_G does not change when a group turns.
// Empty: no turn.
struct GroupAngles {
  const PlacementGroups* groups = nullptr;
  std::vector<double> angle;  // one per group of *groups
  Eigen::Matrix2d of(int v) const;  // the rotation of vertex v's group
};

class GapPull {
 public:
  // keys: X_i (n x 2 each, normalized units), the cohesive terms' keys. One pull per distinct pair
  // that some key leaves open.
  GapPull(const Multimesh& mesh, const std::vector<Eigen::MatrixX2d>& keys, const CohesiveEnergy& cohesive,
          const CohesiveParams& params);

  void setParams(const CohesiveParams& params) { params_ = params; }
  bool empty() const { return pulls_.empty(); }

  // Takes B_j for every pull and open key from x (n x 2, the frame's blend): at the start of a frame's solve.
  void freezeRotations(const Eigen::MatrixX2d& x);

  // Returns W_G at x with weights w, the anchors B_j turned by their group's angle, and adds its
  // gradient at fixed angles (n x 2); with angleGradient (one entry per group, zeroed by the
  // caller), also adds d W_G / d angle per group, for the caller to carry through the angles.
  double evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, Eigen::MatrixX2d& gradient,
                  const GroupAngles& angles = {}, std::vector<double>* angleGradient = nullptr) const;

  // The isotropic spring constant of pull p's pair at weights w (sum over its open keys of
  // w_j (1 - r) l/3 lambda), for the global matrix; pair(p) its vertices.
  double springConstant(int p, const Eigen::VectorXd& w) const;
  // springConstant over the pair's full l/3 lambda: in [0, 1].
  double strength(int p, const Eigen::VectorXd& w) const;
  const CohesivePair& pair(int p) const { return pulls_[p].pair; }
  int size() const { return static_cast<int>(pulls_.size()); }

 private:
  struct Pull;
  // The pull's share at w: its open keys' total weight through 1 - releaseRamp; 0 under kTau.
  double share(const Pull& pull, const Eigen::VectorXd& w) const;

  struct Pull {
    CohesivePair pair;
    int term = 0;           // its first cohesive term (for its cut's timing)
    double restLength = 0;  // l, as the cohesive term's
    Triangle at, ac;        // a triangle at vertex a and one at vertex c
    // Per open key: its index, U_j, V_j, and D(X_j)^{-1} of the two triangles.
    std::vector<int> key;
    std::vector<Eigen::Vector2d> U, V;
    std::vector<Eigen::Matrix2d> Ma, Mc;
    std::vector<Eigen::Matrix2d> R;  // B_j, the frozen anchor rotations (identity until freezeRotations)
    int chain = 0;                   // the cut (pairs end to end, open in the same keys) it turns with
  };
  CohesiveParams params_;
  // Per chain and open key, the chain's minimizing rotation at x (chain * width + key slot).
  std::vector<Eigen::Matrix2d> rotations(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, const GroupAngles& turn) const;

  // Calls visit(pull, slot, u, v, o, k) for every pull with a share at w and every open key slot
  // whose weight k = w_j share l/3 lambda is > 0 (u, v: the pair's gaps at x; o: open keys' weight).
  template <class Visit>
  void forEachTerm(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, Visit&& visit) const;

  std::vector<Pull> pulls_;
  int chains_ = 0;
  size_t slots_ = 0;  // the most open keys of any pull: rotations() holds chains_ x slots_
};

}  // namespace ib
