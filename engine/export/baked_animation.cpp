#include "export/baked_animation.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace ib::gltf {

BakedAnimation bakeAnimation(FrameStream& stream, const render::CutSides& cutSides, std::array<int, 2> range,
                             const std::function<void(int done, int total)>& progress) {
  if (range[0] < 0 || range[1] < range[0] || range[1] >= stream.frameCount())
    throw std::invalid_argument("bakeAnimation: frames " + std::to_string(range[0]) + ".." + std::to_string(range[1]) +
                                " outside the timeline's 0.." + std::to_string(stream.frameCount() - 1));
  BakedAnimation baked;
  baked.fps = stream.timeline().fps();
  baked.loops = stream.timeline().loops() && range[0] == 0 && range[1] == stream.frameCount() - 1;
  baked.shapeSize = stream.shapeSize();
  stream.restart();
  const int total = range[1] + 1;
  while (stream.nextFrame() <= range[1]) {
    AnimationFrame frame = stream.next();
    if (frame.index >= range[0]) {
      baked.frames.push_back(frame.index);
      baked.times.push_back((frame.index - range[0]) / baked.fps);
      render::CutWeld weld = render::weldCuts(frame.x, cutSides, 1.0, {}, &frame.heldPairs);
      baked.positions.push_back(std::move(weld.positions));
      baked.closure.push_back(std::move(weld.closure));
      baked.weights.push_back(std::move(frame.weights));
    }
    if (progress) progress(frame.index + 1, total);
  }
  return baked;
}

}  // namespace ib::gltf
