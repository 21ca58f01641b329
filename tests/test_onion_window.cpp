#include "animation/timeline.h"
#include "output/onion_window.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <vector>

using namespace ib;
using namespace ib::render;

namespace {

struct Drawn {
  int frame = 0, before = -1, after = -1;  // window[at], and its nearest neighbours' indices (-1: none)
};

std::vector<Drawn> play(FrameStream& stream, std::array<int, 2> range, int neighbours) {
  std::vector<Drawn> out;
  playWithNeighbours(stream, range, neighbours, [&](const std::deque<AnimationFrame>& window, size_t at) {
    out.push_back({window[at].index, at > 0 ? window[at - 1].index : -1, at + 1 < window.size() ? window[at + 1].index : -1});
    CHECK(window.size() <= static_cast<size_t>(2 * neighbours + 1));
  });
  return out;
}

}  // namespace

TEST_CASE("onion window: every frame in range is drawn once, in order, with its solved neighbours beside it") {
  const auto f = test::strip(100, 2);
  FrameStream stream(f.mesh, defaultTimeline({"a", "b"}, 24), {}, {}, {});  // frames 0..24
  const std::vector<Drawn> middle = play(stream, {3, 6}, 1);
  REQUIRE(middle.size() == 4);
  for (int k = 0; k < 4; ++k) {
    CHECK(middle[k].frame == 3 + k);
    CHECK(middle[k].before == 2 + k);
    CHECK(middle[k].after == 4 + k);
  }
  CHECK_FALSE(stream.done());  // frames past the last one's neighbours are not solved
  stream.restart();
  const std::vector<Drawn> ends = play(stream, {0, 24}, 2);
  REQUIRE(ends.size() == 25);
  CHECK(ends.front().before == -1);  // the timeline's first frame has no earlier neighbour
  CHECK(ends.front().after == 1);
  CHECK(ends.back().frame == 24);
  CHECK(ends.back().after == -1);
  stream.restart();
  const std::vector<Drawn> plain = play(stream, {5, 5}, 0);
  REQUIRE(plain.size() == 1);
  CHECK(plain[0].before == -1);
  CHECK(plain[0].after == -1);
}

TEST_CASE("onion window: neighbours are faded by distance, earlier tinted red and later green") {
  const auto f = test::strip(100, 2);
  FrameStream stream(f.mesh, defaultTimeline({"a", "b"}, 24), {}, {}, {});
  std::deque<AnimationFrame> window;
  for (int k = 0; k < 5; ++k) window.push_back(stream.next());
  OnionStyle style;
  style.neighbours = 2;
  const FrameDraw draw = frameWithOnionSkins(window, 2, style, {0, 0, 1, 1}, {});
  CHECK(draw.positions == &window[2].x);
  CHECK(draw.heldPairs == &window[2].heldPairs);
  REQUIRE(draw.onion.size() == 4);
  CHECK(draw.onion[0].positions == &window[1].x);
  CHECK(draw.onion[0].tint == style.before);
  CHECK(draw.onion[1].positions == &window[3].x);
  CHECK(draw.onion[1].tint == style.after);
  CHECK(draw.onion[0].opacity == Approx(style.opacity));
  CHECK(draw.onion[2].opacity == Approx(style.opacity / 2));
  CHECK(frameWithOnionSkins(window, 0, style, {0, 0, 1, 1}, {}).onion.size() == 2);  // only later neighbours
  style.neighbours = kMaxOnionSkins;
  CHECK_THROWS_AS(frameWithOnionSkins(window, 2, style, {0, 0, 1, 1}, {}), std::invalid_argument);
}
