// The paper's own solver (section 7.1), written independently for comparison: plain
// local-global where the global matrix is the full 2n x 2n quadratic of the current local step,
// the anisotropic cohesive P inside it, rebuilt and refactorized every iteration. Slow; tests only.
#pragma once

#include "interpolation/cohesive_energy.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>

namespace ib::test {

// Minimizes sum_i w_i [W_C + W_D] from `start` (multimesh units) until the step is below
// stepTolerance * shape size or maxIterations pass; lambda and tau in normalized units (lengths
// divided by sqrt(mean key area)), as the Interpolator takes them.
Eigen::MatrixX2d referenceLocalGlobal(const Multimesh& mesh, const Eigen::VectorXd& w, const CohesiveParams& params,
                                      const Eigen::MatrixX2d& start, int maxIterations, double stepTolerance);

}  // namespace ib::test
