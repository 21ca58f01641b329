// The parameters of the interpolation energies (eq. 9): the cohesive energy W_C (eqs. 10-13;
// cohesive_energy.h), the non-overlap term and the shape metric, on their own so that the scene
// and the interpolator's public header need not include the energies. The scene file's fields and
// their ranges are in scene/parameters.h; the defaults here are the table's.
#pragma once

#include "interpolation/shape_metric.h"

#include <limits>
#include <vector>

namespace ib {

// When a cut lets go (docs/solver.md, "Cut timing").
enum class CutTiming {
  kRelease,  // by the weights: the closed keys' pull fades as the open keys' weight o passes
             // `release` over `releaseWindow`, and the open keys pull the sides to their drawn gap
  kTau,      // by the energy: a cut lets go when a pair's cohesive energy exceeds tau (the paper),
             // all its pairs at once, and stays apart until the weights go back (cohesive_energy.h)
};

// One cut's own timing (a scene cut's "release" and "release_window"); NaN: the scene's.
struct CutRelease {
  double release = std::numeric_limits<double>::quiet_NaN();
  double window = std::numeric_limits<double>::quiet_NaN();
};

// Cohesive parameters in normalized units (lengths divided by the shape size).
struct CohesiveParams {
  double lambda = 4000.0;  // cohesive stiffness lambda (eq. 10); paper default 4e3
  double tau = 1e-3;       // clamp threshold tau (eq. 11): normalized energy per cohesive pair (lengths in
                           // shape sizes); infinity never separates. CutTiming::kTau only
  double alpha = 0.5;      // shear/stretch control alpha in [0, 1] (eq. 13): the jump along the
                           // edge costs (1 - alpha), across it alpha; larger alpha = easier shear
  CutTiming timing = CutTiming::kRelease;
  double release = 0.5;        // the open keys' total weight at the middle of the window over which
                               // a cut lets go, in [0, 1]
  double releaseWindow = 1.0;  // the span of that weight over which it fades, in (0, 1], kept
                               // within [0, 1] (so a closed key is glued and an open key open);
                               // default 1: the sides part over the whole segment (bench pops,
                               // docs/benchmarks.md)
  // Per cohesive term, in the multimesh's order (key 0's pairs, then key 1's, ...): the term's
  // cut's own timing where the scene gives one (pipeline/cut_release.h). Empty: the two above
  // for every cut. Default empty.
  std::vector<CutRelease> perTerm = {};
};

// What fixes where a shape stands (placement.h): the rigid motion every group of vertices may take
// freely.
enum class Placement {
  kBlend,  // every vertex alike: each group's rigid fit to the keys' blend (the paper's frame)
  kStill,  // vertices drawn at the same place in every key weigh 99 times more in that fit, so a
           // body drawn the same in every key stays where it was drawn while a limb moves
           // ("correspondence": "artwork"; docs/drawings-to-multimesh.md)
};

struct InterpolationParams {
  CohesiveParams cohesive;  // lambda, tau, alpha (normalized units)
  bool nonOverlap = false;  // enforce W_O (eq. 14); off by default, as in the paper
  // How each triangle's keys are averaged (shape_metric.h): kShared, one metric per triangle
  // blended by the weights (no shrinking or snapping under stretch; a departure from the paper),
  // or kPerKey, the paper's eq. 9. Default kShared (docs/solver.md, "Departures from the paper").
  ShapeMetric metric = ShapeMetric::kShared;
  // Default kBlend; sceneFrameSetup sets kStill for "correspondence": "artwork" (the scene's
  // choice, also when its multimesh was built by arc length after a fold).
  Placement placement = Placement::kBlend;
};

}  // namespace ib
