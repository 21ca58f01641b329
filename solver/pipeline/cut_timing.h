// Each cut's timing in a scene (docs/scene-format.md, "Cut timing"): for the solver, every
// cohesive term's own release and window (CohesiveParams::perTerm), and for a scrubber, the
// times the timeline lets each cut go and glues it.
#pragma once

#include "interpolation/interpolation_params.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace ib {

class Multimesh;

// One CutRelease per cohesive term of `mesh` (a multimesh of `scene`, in its term order: key 0's
// pairs, then key 1's, ...), each the timing of the cut whose polyline the pair lies on in the
// key that closes it (NaN fields: the scene's). Empty when no cut gives its own.
std::vector<CutRelease> cutReleases(const Scene& scene, const Multimesh& mesh);

// A cut letting go (its open keys' total weight rising past its release) or gluing (falling
// past it) on the scene's timeline, at the first frame past it.
struct CutEvent {
  std::string cut;
  double time = 0;  // s, the timeline's frame time
  int frame = 0;
  bool glue = false;  // false: it lets go
};
// Under CutTiming::kRelease (none under kTau): every cut's events, in time order.
std::vector<CutEvent> cutEvents(const Scene& scene);
// The summed weight at timeline frame `frame` of the keys where `cut` is open (that do not draw
// it): the cut lets go where this crosses its release, so dragging its marker to a frame sets the
// release to this value there.
double openWeight(const Scene& scene, const std::string& cut, int frame);

}  // namespace ib
