#include "output/onion_window.h"

#include <stdexcept>
#include <string>

namespace ib::render {

void playWithNeighbours(FrameStream& stream, std::array<int, 2> range, int neighbours,
                        const std::function<void(const std::deque<AnimationFrame>& window, size_t at)>& draw) {
  if (neighbours < 0) throw std::invalid_argument("onion window: neighbours must be >= 0");
  std::deque<AnimationFrame> window;
  size_t next = 0;  // index into window of the next frame to draw
  auto drawIfInRange = [&](size_t at) {
    if (window[at].index >= range[0] && window[at].index <= range[1]) draw(window, at);
  };
  while (!stream.done()) {
    AnimationFrame frame = stream.next();
    if (frame.index > range[1] + neighbours) break;
    if (frame.index < range[0] - neighbours) continue;
    window.push_back(std::move(frame));
    for (; next < window.size() && window[next].index + neighbours <= window.back().index; ++next) drawIfInRange(next);
    for (; next > static_cast<size_t>(neighbours); --next) window.pop_front();  // no longer anyone's neighbour
  }
  for (; next < window.size(); ++next) drawIfInRange(next);
}

FrameDraw frameWithOnionSkins(const std::deque<AnimationFrame>& window, size_t at, const OnionStyle& style,
                              const ViewBox& view, const Overlays& overlays) {
  if (at >= window.size()) throw std::invalid_argument("onion window: frame " + std::to_string(at) + " is not in the window");
  if (style.neighbours < 0 || 2 * style.neighbours > kMaxOnionSkins)
    throw std::invalid_argument("onion window: at most " + std::to_string(kMaxOnionSkins / 2) + " neighbours each side");
  const AnimationFrame& frame = window[at];
  FrameDraw request;
  request.positions = &frame.x;
  request.weights = frame.weights;
  request.heldPairs = &frame.heldPairs;
  request.view = view;
  request.overlays = overlays;
  for (int d = 1; d <= style.neighbours; ++d) {
    const float opacity = style.opacity / d;
    const auto skin = [&](const AnimationFrame& f, std::array<float, 3> tint) {
      return OnionSkin{&f.x, f.weights, tint, opacity, &f.heldPairs};
    };
    if (at >= static_cast<size_t>(d)) request.onion.push_back(skin(window[at - d], style.before));
    if (at + d < window.size()) request.onion.push_back(skin(window[at + d], style.after));
  }
  return request;
}

}  // namespace ib::render
