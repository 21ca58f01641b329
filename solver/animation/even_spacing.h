// Even spacing (docs/animation.md, "Even spacing"): re-times a timeline segment so that its shape
// changes by equal amounts per unit of eased time. Equal steps of the weights do not give equal
// steps of the shape (with the per-key metric a stretched shape snaps into its key 2-5x faster than
// mid-segment), so for each segment that asks for it (TimelineSegment::spacingKind = kEven) the
// path is sampled at K points, the plain inbetween solved at each (warm-started along the path),
// and the arc length L(p) = sum of RMS vertex moves (shape sizes) becomes the segment's spacing
// table; Timeline::weights then walks the path at p = L^-1(ease(u)). Cost: K solves per segment,
// once, before the first frame. Deterministic: the same timeline, multimesh and parameters give
// the same tables bit for bit.
#pragma once

#include "animation/timeline.h"
#include "interpolation/interpolator.h"

#include <functional>
#include <vector>

namespace ib {

struct EvenSpacingOptions {
  int samples = 33;  // K: path points per segment, p_j = j / (K - 1); K solves per segment, >= 2
  // A step longer than jumpRatio times the longer of its two neighbours counts only that much: the
  // shape jumping at one instant of the path (a solve falling into another minimum) is not a pace
  // to slow down for. Smooth snap near a key changes by far less than 2x from one sample to the
  // next. > 1.
  double jumpRatio = 2;
};

// The shape's change along one segment's path, sampled at p_j = j / (K - 1).
struct PathSamples {
  std::vector<double> steps;      // K - 1: RMS vertex move from sample j to j + 1, in shape sizes
  std::vector<char> pairsChange;  // K - 1: some cohesive pair lets go or glues between j and j + 1
};

// fraction in [0, 1] of the solves done.
using SpacingProgress = std::function<void(double fraction)>;

// True when some segment asks for even spacing and carries no table yet.
bool needsEvenSpacing(const Timeline& timeline);

// Segment k's path sampled: the plain inbetweens at p_j = j / (samples - 1), each solved from the
// one before (the first from `start` when given, n x 2, else the blend of the keys). last, when
// given, gets the inbetween at p = 1.
PathSamples samplePath(const Timeline& timeline, int segment, Interpolator& solver, int samples,
                       const Eigen::MatrixX2d* start = nullptr, Eigen::MatrixX2d* last = nullptr,
                       const SpacingProgress& progress = nullptr);

// The spacing table (TimelineSegment::spacing) of a sampled path: the running sum of its steps over
// their total. Jumps first count as the pace around them: a step where cohesive pairs let go or
// glue (the shape jumps to the pieces' new rest, a cascade of such steps as a cut unzips) counts as
// the nearest steps on either side without one, interpolated (spreading frames over a release
// would only show it in slow motion, each frame still a jump); any other step at most jumpRatio
// times its longer neighbour; then each is raised to at least 1e-3 of the mean, so the table
// increases strictly. Empty when the path does not move the shape (total under 1e-12 shape sizes,
// or every step a release): the identity.
std::vector<double> spacingTable(const PathSamples& path, const EvenSpacingOptions& options = {});

// The timeline with a spacing table on every kEven segment that has none (a hold or a path that
// stays at one pose keeps none); everything else as given. `solver` is an Interpolator over the
// timeline's multimesh with the parameters to be played; its history is forgotten afterwards, so
// its next solve is a fresh Interpolator's. InputError for options out of range.
Timeline evenSpacing(const Timeline& timeline, Interpolator& solver, const EvenSpacingOptions& options = {},
                     const SpacingProgress& progress = nullptr);

}  // namespace ib
