// What `inbetween export` bakes: the timeline's frames as the renderer shows them, solved in order
// (dynamics included) with the held cohesive pairs welded (render::weldCuts), and each frame's
// interpolation weights for the artwork cross-fade.
#pragma once

#include "animation/frame_stream.h"
#include "output/render_mesh.h"

#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

namespace ib::gltf {

struct BakedAnimation {
  std::vector<int> frames;                   // frame numbers, consecutive, in order
  std::vector<double> times;                 // s, from the first baked frame (frame f at (f - first) / fps)
  std::vector<Eigen::MatrixX2d> positions;   // [frame]: n x 2, welded, drawing pixels (y down)
  std::vector<Eigen::VectorXd> weights;      // [frame]: m x 1, the interpolation weights w(s)
  std::vector<std::vector<float>> closure;   // [frame]: n, how shut each vertex's cut is (weldCuts;
                                             // empty: no ink drawn on opened cuts)
  double fps = 24;                           // frames per second
  bool loops = false;                        // the whole looping timeline: the clip returns to its first frame
  double shapeSize = 1;                      // s = sqrt(mean key area), drawing pixels
};

// Plays `stream` from its start and bakes the frames of `range` (inclusive, within the timeline).
// Welding uses weldCuts at one target pixel per drawing pixel: partners within half a drawing pixel
// meet, held pairs always. `progress(done, total)` after each frame solved (optional). Throws
// std::invalid_argument for a range outside the timeline.
BakedAnimation bakeAnimation(FrameStream& stream, const render::CutSides& cutSides, std::array<int, 2> range,
                             const std::function<void(int done, int total)>& progress = {});

}  // namespace ib::gltf
