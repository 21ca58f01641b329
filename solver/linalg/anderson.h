// Anderson acceleration (type II, Walker & Ni 2011) of a fixed-point map G, as used for
// local-global solvers by Peng et al. 2018: from the last `depth` iterates x_k, their images
// G(x_k) and residuals f_k, the next iterate is G(x_k) - dG gamma, with gamma minimizing
// |f_k - dF gamma|. The residual is any vector that vanishes at the fixed point; the solver passes
// the energy gradient, the quantity its stopping rule measures (the usual f = G(x) - x is the
// preconditioned gradient, which underweights the high-frequency error the rule sees).
// The caller safeguards it: an accelerated iterate that raises the energy is rejected and the
// history reset.
#pragma once

#include "core/thread_block.h"

#include <Eigen/Core>

namespace ib {

class AndersonAcceleration {
 public:
  static constexpr int kMaxDepth = 16;
  // depth: history length, 0..kMaxDepth (0 disables acceleration); threads: for the O(size) passes.
  AndersonAcceleration(int depth, int threads);

  // From now on the vectors are `segments` equal parts stacked (2: the columns of an n x 2
  // matrix, rows.size() = n), and thread p takes rows [rows.begin(p), rows.end(p)) of every part:
  // the same vertices as in the caller's own loops. Default: the vector split evenly.
  void setRowSplit(RowSplit rows, int segments);

  void reset();
  // Keeps the stored differences but forgets the last iterate, for a new but similar map
  // (the next frame): the old secant information then seeds the first steps.
  void restart();
  // gx: G(x) for the current iterate x; residual: its residual; out: receives the accelerated
  // next iterate (gx itself with no history yet, or depth 0). All of the same size.
  void next(const Eigen::Ref<const Eigen::VectorXd>& gx, const Eigen::Ref<const Eigen::VectorXd>& residual,
            Eigen::Ref<Eigen::VectorXd> out);

 private:
  // The differences are stored in single precision: they only set the mixing coefficients and
  // the size of a step whose energy the caller checks, and half the bytes make the passes faster.
  using History = Eigen::MatrixXf;
  int depth_, threads_;
  RowSplit rows_;    // setRowSplit's split of each segment (empty: even over the whole vector)
  int segments_ = 1;
  int stored_ = 0, newest_ = -1;
  bool havePrevious_ = false;
  Eigen::VectorXd previousF_, previousG_;
  History dF_, dG_;         // size x depth ring buffers of differences, one column each
  Eigen::MatrixXd gram_;    // depth x depth, dF^T dF kept up to date column by column
};

}  // namespace ib
