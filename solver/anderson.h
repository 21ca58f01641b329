// Anderson acceleration (type II, Walker & Ni 2011) of a fixed-point map G, as used for
// local-global solvers by Peng et al. 2018: from the last `depth` iterates x_k and their images
// G(x_k), the next iterate is G(x_k) - dG gamma, with gamma minimizing |f_k - dF gamma|, f = G(x) - x.
// The caller safeguards it: an accelerated iterate that raises the energy is rejected and the
// history reset.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace ib {

class AndersonAcceleration {
 public:
  explicit AndersonAcceleration(int depth);

  void reset();
  // Keeps the stored differences but forgets the last iterate, for a new but similar map
  // (the next frame): the old secant information then seeds the first steps.
  void restart();
  // x: current iterate, gx: G(x) (same size). Returns the accelerated next iterate; with no
  // history yet (or depth 0) that is gx itself.
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& gx);

 private:
  int depth_;
  int stored_ = 0, newest_ = -1;
  Eigen::VectorXd previousF_, previousG_;
  Eigen::MatrixXd dF_, dG_;  // size x depth, ring buffers of differences
  Eigen::MatrixXd gram_;     // depth x depth, dF^T dF kept up to date column by column
};

}  // namespace ib
