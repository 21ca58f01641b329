// W_C, the clamped cohesive energy of eqs. (10)-(13), summed over keys with their weights:
//   W_C(C_i, x) = sum_j min( l_ij / 3 * d(C_i^j, x), tau ),
//   d = lambda [u; v]^T [[P, P/2], [P/2, P]] [u; v],   u = x^a - x^c,  v = x^b - x^d,
//   P = alpha Id + (1 - 2 alpha) xhat xhat^T,          xhat ~ x^a + x^c - x^b - x^d.
// P is evaluated from the current x in the local step and kept out of the global matrix (which
// holds an isotropic spring that majorizes it). The gradient is the exact one, including the
// dependence of xhat on x: with xhat frozen (as the paper's iteration treats it) the gradient
// is not rotation invariant and carries a net torque, so a rotation-gauged solve could not
// drive it to zero. A pair is *held* while l/3 d < tau (under CutTiming::kRelease: while its
// term weight, the release ramp, is above 0); a clamped pair costs tau and exerts
// no force. Under CutTiming::kTau a cut whose pair let go in a solved frame lets go as one and stays
// apart until the weights go back past that point (letGo below): it does not glue again by
// chance as its sides drift within tau, so when it lets go moves with tau monotonically.
#pragma once

#include "interpolation/interpolation_params.h"
#include "interpolation/deformation_energy.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

// CutTiming::kRelease: the share r of a cut's closing pull at the open keys' total weight o, 1
// below lo = release - window/2, 0 above hi = release + window/2 (both kept within [0, 1]), and
// between them such that the gap, (1 - r) o of the drawn one, is hi G(u) with G(u) = 2u^2 - u^3,
// u = (o - lo) / (hi - lo): at rest where it parts, at most 4/3 as fast as the weights. The gap
// pull (gap_pull.h) takes the rest, 1 - r.
double releaseRamp(double openWeight, double release, double window);
double releaseRamp(double openWeight, const CohesiveParams& params);  // the scene's release and window
// The gap pull's fade after the window: 1 up to release + window/2, 0 from a window further on
// (both kept within [0, 1]), a smoothstep between. Once the closing pull is gone the pieces are
// free again (placed on the blend, shaped by E_D), where the pull's target, the open keys' gap
// scaled by o, already put them.
double pullFade(double openWeight, double release, double window);
// Term j's release and window: its cut's own (CohesiveParams::perTerm) or the scene's.
CutRelease timingOf(int term, const CohesiveParams& params);

struct CohesiveTerm {
  int key = 0;
  CohesivePair pair;
  double restLength = 0;           // l_ij, eq. (12)
  Eigen::Vector2d restDirection;   // fallback xhat when the deformed edges collapse
  std::vector<char> closedIn;      // [key]: 1 where the pair is among that key's cohesive pairs
  int cut = 0;                     // its cut: the chain of pairs it belongs to (cut_chains.h)
};

class CohesiveEnergy {
 public:
  // keys: X_i (n x 2 each, normalized units).
  CohesiveEnergy(const Multimesh& mesh, const std::vector<Eigen::MatrixX2d>& keys, const CohesiveParams& params);

  const std::vector<CohesiveTerm>& terms() const { return terms_; }
  // lambda, tau and alpha for the next evaluations (the terms stay).
  void setParams(const CohesiveParams& params) { params_ = params; }

  // Returns sum_i w_i W_C(C_i, x), adds its gradient to gradient (n x 2) and sets
  // held[j] for every term j (false for terms of keys with zero weight).
  double evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, Eigen::MatrixX2d& gradient,
                  std::vector<char>& held) const;

  // Term j's weight at w: w(key), under CutTiming::kRelease times the release ramp of the open
  // keys' total weight (1 below release - window/2, 0 above release + window/2, smooth between).
  double termWeight(int term, const Eigen::VectorXd& w) const;
  // Term j's release ramp at w (releaseRamp of its open keys' weight; 1 under CutTiming::kTau).
  double ramp(int term, const Eigen::VectorXd& w) const;
  // Under CutTiming::kRelease: whether term j glues at w (its ramp is 1: the sides are shut).
  bool glued(int term, const Eigen::VectorXd& w) const;

  // CutTiming::kTau's memory of cuts that let go, kept by a stream of solves (Interpolator):
  // after a solved frame, `letGo` marks every cut with a term of nonzero weight not held there
  // (its energy passed tau) with the frame's weights w_L and the direction d = w_L - w_prev they
  // were moving in (w_prev: the previous letGo call's weights); before a frame, `holdAgain`
  // forgets the cuts the weights went back past, (w - w_L) . d < 0, where the energy decides
  // again. A cut that lets go on the stream's first frame or on a held frame (d = 0) is not
  // marked. Every term of a marked cut costs tau and exerts no force. forgetLetGo: none marked,
  // no previous weights.
  void letGo(const std::vector<char>& held, const Eigen::VectorXd& w);
  void holdAgain(const Eigen::VectorXd& w);
  void forgetLetGo();

  // Isotropic spring constant standing in for term j in a matrix shared by x and y:
  // l/3 lambda max(alpha, 1 - alpha), the largest eigenvalue of its P, so the spring majorizes it.
  double springConstant(int term) const;

 private:
  CohesiveParams params_;
  std::vector<CohesiveTerm> terms_;
  struct LetGo {
    Eigen::VectorXd at, direction;  // w_L and d (m x 1 each); empty: not let go
  };
  std::vector<LetGo> letGo_;      // [cut], under CutTiming::kTau (letGo)
  Eigen::VectorXd lastWeights_;   // the weights of the last letGo call; empty: none yet
};

}  // namespace ib
