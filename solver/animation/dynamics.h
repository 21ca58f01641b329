// Dynamic effects for variational interpolation (paper section 6.1), and the blending controller
// that drives them from one compliance epsilon (the paper's supplement is not available; this
// design is ours and documented in docs/animation.md, "Dynamics").
//
// A frame s with dynamics minimizes W_I(x, w(s)) + W_T(x, xi) + W_A(x):
//   x_p   = x(s-1) + h e^{-mu h} v(s-1) + h^2 a(s)              eq. 17, damping as exact velocity decay
//   W_T   = xi / (2 h^2) (x - x_p)^T M (x - x_p)                 eq. 18
//   W_A   = k_A / 2 sum_v a_v m_v |x_v - xbar_v(s)|^2            anchor to the plain inbetween xbar(s)
// with v(s-1) = (x(s-1) - x(s-2)) / h from the frames actually shown, M = diag(m_v) lumped vertex
// masses, a(s) = gravity + wind(s). W_I and W_T alone leave the shape's rigid motion to ballistics
// (nothing in W_I holds a shape's position), so a shape would fall out of the picture under
// gravity; the anchor ties it to where the animation puts it. Anchor weights a_v follow the painted
// stiffness (kappa_v / max kappa): stiff regions keep to the animation, soft ones swing and droop.
//
// The controller sets xi through the blend beta in [0, 0.95]: xi / h^2 = k_A beta / (1 - beta)
// (at beta = 1/2 inertia and a fully anchored vertex's anchor are equally strong), with
//   beta(s) = epsilon * fade(s) / (1 + (D(s-1) / (epsilon D_max))^2),
// fade(s) = 0 at every mark (so every mark, and so every drawn key, is hit: xi = 0 there), 1 right
// after it (follow-through: a shape that arrives at a key with speed overshoots it), falling
// smoothly to 0 over the last `settle` of each segment (the shape settles onto the next mark), and
// D(s-1) the last frame's deviation from its plain inbetween: the further dynamics has pulled the
// shape from the drawn motion, the harder the controller pulls back. epsilon = 0 is plain
// interpolation. Positions stay continuous where beta jumps: beta only weighs inertia.
#pragma once

#include "animation/timeline.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>

namespace ib {

struct DynamicsParams {
  double epsilon = 0;              // compliance in [0, 1]; 0 = plain interpolation. Default 0
  Eigen::Vector2d gravity{0, 0};   // shape sizes per s^2, y down (as in drawings). Default none
  Eigen::Vector2d wind{0, 0};      // shape sizes per s^2. Default none
  double gust = 0;                 // wind(s) = wind (1 + gust sin(2 pi gustFrequency s)); [0, 1]. Default 0
  double gustFrequency = 0.5;      // Hz, > 0. Default 0.5
  double mu = 0.5;                 // damping, 1/s: the force -mu M v. Default 0.5 (paper Table 3's typical)
  double anchor = 0.1;             // k_A relative to Interpolator::stiffnessScale() per mean vertex mass, > 0. Default 0.1
  double settle = 0.25;            // share of a segment's end over which dynamics fade out, (0, 1]. Default 0.25
  double maxDeviation = 0.25;      // D_max, shape sizes: the deviation budget at epsilon = 1, > 0. Default 0.25

  bool enabled() const { return epsilon > 0; }
};

// The fade in [0, 1] at a timeline position: 0 at marks and outside segments, 1 from just after a
// mark until the last `settle` of the segment.
double dynamicsFade(const DynamicsParams& params, const Timeline::Position& position, int segmentCount);

// The controller's blend beta in [0, 0.95] for a frame at `position` after a frame that deviated
// by `deviation` shape sizes from its plain inbetween.
double dynamicsBlend(const DynamicsParams& params, const Timeline::Position& position, int segmentCount,
                     double deviation);

// Lumped vertex masses m_v (n x 1): a third of each incident triangle's area, averaged over the
// keys, normalized to sum 1.
Eigen::VectorXd lumpedMasses(const Multimesh& mesh);

// Anchor weights a_v in (0, 1] (n x 1): area-weighted mean kappa of the incident triangles over
// the largest such mean.
Eigen::VectorXd anchorWeights(const Multimesh& mesh);

// The external acceleration at time s (shape sizes per s^2).
Eigen::Vector2d externalAcceleration(const DynamicsParams& params, double time);

// Checks the parameters; throws InputError naming the field (prefixed by `where`).
void validateDynamics(const DynamicsParams& params, const std::string& where);

}  // namespace ib
