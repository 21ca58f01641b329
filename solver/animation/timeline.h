// The timeline (paper section 6): interpolation weights w(s) over time s, in seconds. Marks
// place keys and breakdowns (blends of keys) at times; the segment leaving each mark has an
// easing and, for an n-way blend, control weights. Properties (tests/test_timeline.cpp):
//   - w(s) is convex at every s (non-negative, summing to 1);
//   - w is continuous in s, except at the end of a "hold" segment, where it steps by design;
//   - at a mark's time, w is that mark's weights exactly (a key mark gives e_i).
// Format: docs/scene-format.md, "timeline"; read by parseTimeline (scene/scene_animation.h).
#pragma once

#include "animation/easing.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ib {

struct TimelineMark {
  double time = 0;          // s
  Eigen::VectorXd weights;  // m x 1, convex; e_i for a key mark
  std::string label;        // the key's name, or "breakdown" (for messages and reports)
};

// The way from one mark to the next. With no controls the weights move straight from the start
// mark's to the end mark's, w = (1 - e) A + e B with e = ease(u). With controls C_1..C_k they
// follow the Bezier curve A, C_1, .., C_k, B in the weight simplex at parameter e: every key's
// weight is its own curve, all stay convex (Bernstein weights are non-negative and sum to 1),
// and the curve still starts at A and ends at B.
//
// Between easing and the path sits the segment's spacing: the path parameter p at eased time e.
// kWeights (the default): p = e, equal steps of the weights. kEven: equal steps of the shape,
// p = L^-1(e) with L(p) the fraction of the segment's shape change (RMS vertex move of the plain
// inbetween) done by path parameter p; easing then paces that evenly changing shape. L depends on
// the solver, so the Timeline only carries its table; evenSpacing (even_spacing.h) fills it, and
// FrameStream does so when a segment asks for kEven without one (docs/animation.md, "Even
// spacing").
enum class SegmentSpacing { kWeights, kEven };

struct TimelineSegment {
  Easing easing;
  std::vector<Eigen::VectorXd> controls;  // m x 1 each, convex
  SegmentSpacing spacingKind = SegmentSpacing::kWeights;
  // The remap table of the path parameter: spacing[j] = L(j / (K - 1)), K >= 2 samples, strictly
  // increasing from exactly 0 to exactly 1. p(e) is its monotone cubic (Fritsch-Carlson) inverse,
  // so p(0) = 0, p(1) = 1 and p never goes back. Empty: p = e (the identity).
  std::vector<double> spacing;
};

// The path parameter p in [0, 1] at eased time e in [0, 1] (clamped) through segment.spacing.
// Deterministic; exactly 0 at 0 and 1 at 1.
double pathParameter(const TimelineSegment& segment, double e);

class Timeline {
 public:
  // A still: one mark at time 0 holding the first of one key, 24 frames per second.
  Timeline();
  // marks: at least one, finite times strictly increasing; segments: marks.size() - 1; fps > 0;
  // each segment's spacing table empty or as TimelineSegment says. Anything else is the caller's error (std::invalid_argument): parseTimeline checks first and
  // names the field.
  Timeline(double fps, bool loop, std::vector<TimelineMark> marks, std::vector<TimelineSegment> segments);

  double fps() const { return fps_; }
  bool loops() const { return loop_; }
  double start() const { return marks_.front().time; }
  double end() const { return marks_.back().time; }
  double duration() const { return end() - start(); }
  const std::vector<TimelineMark>& marks() const { return marks_; }
  const std::vector<TimelineSegment>& segments() const { return segments_; }
  int keyCount() const { return static_cast<int>(marks_.front().weights.size()); }

  // Frames sit at start() + f / fps. A plain timeline includes a frame at its end when the end
  // falls on one; a looping one stops before its end, which repeats its start.
  int frameCount() const;
  double frameTime(int frame) const;

  // Where time s falls: the segment (-1 before the first mark, segments().size() after the last,
  // with u = 0) and the fraction u in [0, 1) through it. A looping timeline wraps s first.
  struct Position {
    int segment = 0;
    double u = 0;
  };
  Position locate(double s) const;

  // w(s): m x 1, convex. Before the first mark and after the last, the nearest mark's weights.
  Eigen::VectorXd weights(double s) const;
  // The weights on segment k's path at path parameter p in [0, 1] (after easing and spacing):
  // its start mark's weights at 0, its end mark's at 1. k in [0, segments().size()).
  Eigen::VectorXd pathWeights(int segment, double p) const;

 private:
  double wrap(double s) const;
  double fps_;
  bool loop_;
  std::vector<TimelineMark> marks_;
  std::vector<TimelineSegment> segments_;
};

// Every key in scene order, one second apart, ease-in-out; a looping one returns to the first key
// a second after the last. A single key is a still of one second (it never loops).
Timeline defaultTimeline(const std::vector<std::string>& keyNames, double fps = 24, bool loop = false);

}  // namespace ib
