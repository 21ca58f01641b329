// The onion-skin frame window: a timeline's frames solved in order (dynamics and warm starts need
// every earlier frame) with each drawn frame's neighbours at hand, and the request that draws a
// frame with its neighbours faded behind it. Shared by `inbetween render` and the player.
#pragma once

#include "animation/frame_stream.h"
#include "output/render_mesh.h"

#include <array>
#include <cstddef>
#include <deque>
#include <functional>

namespace ib::render {

// Plays `stream` from where it stands and calls draw(window, at) for every frame whose index is
// in `range` (inclusive), in order, once the `neighbours` frames after it are solved too:
// window[at] is the frame, with up to `neighbours` solved frames on each side (fewer at the
// timeline's ends). Frames past range[1] + neighbours are not solved.
void playWithNeighbours(FrameStream& stream, std::array<int, 2> range, int neighbours,
                        const std::function<void(const std::deque<AnimationFrame>& window, size_t at)>& draw);

// How neighbours look behind a frame: frame at - d and at + d, for d = 1..neighbours, at opacity
// `opacity` / d, earlier ones tinted red, later ones green (as Blender's and Spine's onion skins).
struct OnionStyle {
  int neighbours = 0;                           // each side, 0..kMaxOnionSkins / 2
  float opacity = 0.35f;                        // of the nearest neighbours, in [0, 1]
  std::array<float, 3> before{1.0f, 0.45f, 0.45f};  // tint of earlier frames
  std::array<float, 3> after{0.45f, 1.0f, 0.45f};   // tint of later frames
};

// The request that draws window[at] over `view` with `overlays`, its neighbours as onion skins
// (pointers into `window`, which must outlive the request).
FrameDraw frameWithOnionSkins(const std::deque<AnimationFrame>& window, size_t at, const OnionStyle& style,
                              const ViewBox& view, const Overlays& overlays);

}  // namespace ib::render
