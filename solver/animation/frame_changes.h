// How much an animation's shape changes from frame to frame, segment by segment: the measure of a
// pop (../shared/topology-change.md). A pop is one frame that changes far more than the frames
// around it: where a cut lets go on one frame instead of over several, the largest change of the
// silhouette in its segment is many times the segment's median change.
#pragma once

#include "animation/frame_stream.h"
#include "animation/timeline.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

// The changes within one segment of the timeline: between consecutive frames f-1 -> f where
// frame f-1 lies in the segment (so the step onto the segment's end mark is its own).
struct SegmentChanges {
  int segment = 0;                // index into Timeline::segments()
  int firstFrame = 0;             // the segment's first frame (f-1 of its first step)
  int steps = 0;                  // frame-to-frame steps measured
  // Silhouette: pixels (of 1 drawing px) covered in one frame and not the other.
  double medianPixels = 0;
  double maxPixels = 0;
  int maxPixelsFrame = 0;         // f of the largest step
  double maxPixelsShare = 0;      // that step's pixels over frame f-1's silhouette area
  // Vertex RMS move, drawing px.
  double medianRms = 0;
  double maxRms = 0;
  int maxRmsFrame = 0;
  // The smallest area of a frame over the area interpolated between the keys, sum_k w_k area(X_k).
  double minAreaRatio = 1;
  int minAreaFrame = 0;
  // Every step's changed pixels and RMS move, in frame order (f = firstFrame + 1 + index).
  std::vector<double> pixelSteps, rmsSteps;
  // The pop the segment's timing gives by itself: the largest step of the weights (L1) over the
  // median. An eased segment moves unevenly whatever the shapes do (an ease-out curve 3.4x).
  double timingPop = 1;
  std::vector<double> weightSteps;
  // Frames f whose held cohesive pairs are fewer (releases) or more (glues) than frame f-1's.
  std::vector<int> releases, glues;
};

// Pixel centres covered by the triangles of `mesh` at positions x (drawing px), on the grid of
// 1 px cells from `origin` (x, y), width x height. [y * width + x]: 1 inside.
std::vector<char> silhouetteMask(const Multimesh& mesh, const Eigen::MatrixX2d& x, const Eigen::Vector2d& origin,
                                 int width, int height);

// The changes of `frames` (the timeline's frames 0..N-1 in order, as a FrameStream gives them) in
// every segment that moves (holds, where the weights do not change, are left out).
std::vector<SegmentChanges> segmentChanges(const Multimesh& mesh, const Timeline& timeline,
                                           const std::vector<AnimationFrame>& frames);

}  // namespace ib
