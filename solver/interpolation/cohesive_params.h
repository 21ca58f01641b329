// The parameters of the cohesive energy W_C (eqs. 10-13; cohesive_energy.h), on their own so
// that the interpolator's public header need not include the energies.
#pragma once

namespace ib {

// Cohesive parameters in normalized units (lengths divided by the shape size).
struct CohesiveParams {
  double lambda = 4000.0;  // cohesive stiffness lambda (eq. 10); paper default 4e3
  double tau = 1e-3;       // clamp threshold tau (eq. 11), energy per pair; infinity never separates
  double alpha = 0.5;      // shear/stretch control alpha in [0, 1] (eq. 13): the jump along the
                           // edge costs (1 - alpha), across it alpha; larger alpha = easier shear
};

}  // namespace ib
