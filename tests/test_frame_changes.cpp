// The measure of a pop (animation/frame_changes.h) on shapes whose answers are known: a square's
// silhouette covers the pixel centres inside it, and a segment whose frames move evenly but for
// one jump has its largest change at that jump, its median at the even move.
#include "animation/frame_changes.h"

#include <catch2/catch.hpp>

using namespace ib;

namespace {

// Two triangles: the square [x0, x0 + side] x [y0, y0 + side], as positions of a 4-vertex mesh.
Eigen::MatrixX2d square(double x0, double y0, double side) {
  Eigen::MatrixX2d x(4, 2);
  x << x0, y0, x0 + side, y0, x0 + side, y0 + side, x0, y0 + side;
  return x;
}

Multimesh squareMesh() {
  Multimesh mesh(4, {{0, 1, 2}, {0, 2, 3}});
  mesh.addKey(square(0, 0, 10), {}, {0, 1, 2, 3});
  mesh.addKey(square(40, 0, 10), {}, {0, 1, 2, 3});
  return mesh;
}

}  // namespace

TEST_CASE("frame changes: a square's silhouette is the pixel centres inside it, either way round") {
  const Multimesh mesh = squareMesh();
  // The square [2.2, 7.8]^2 holds the centres 2.5 .. 7.5: 6 x 6 pixels, on a grid from (0, 0).
  const std::vector<char> mask = silhouetteMask(mesh, square(2.2, 2.2, 5.6), {0, 0}, 12, 12);
  int covered = 0;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) {
      const bool inside = x >= 2 && x <= 7 && y >= 2 && y <= 7;
      CHECK(mask[y * 12 + x] == (inside ? 1 : 0));
      covered += mask[y * 12 + x];
    }
  CHECK(covered == 36);
  // Mirrored (every triangle inverted), the same pixels.
  Eigen::MatrixX2d mirrored = square(2.2, 2.2, 5.6);
  mirrored.col(0) = 10.0 - mirrored.col(0).array();
  const std::vector<char> flipped = silhouetteMask(mesh, mirrored, {0, 0}, 12, 12);
  CHECK(std::count(flipped.begin(), flipped.end(), 1) == 36);
}

TEST_CASE("frame changes: one jump in an evenly moving segment is its largest step, many times its median") {
  const Multimesh mesh = squareMesh();
  // Two keys 1 s apart at 10 fps: frames 0..10. The square moves 1 px a frame, but 20 px at frame 6.
  const Timeline timeline(10, false, {{0, Eigen::Vector2d(1, 0), "a"}, {1, Eigen::Vector2d(0, 1), "b"}},
                          std::vector<TimelineSegment>(1));
  std::vector<AnimationFrame> frames;
  double at = 0;
  for (int f = 0; f <= 10; ++f) {
    if (f > 0) at += f == 6 ? 20 : 1;
    AnimationFrame frame;
    frame.index = f;
    frame.weights = timeline.weights(timeline.frameTime(f));
    frame.x = square(at, 0, 10);
    frame.heldPairs = {f < 6 ? char(1) : char(0)};
    frames.push_back(frame);
  }
  const std::vector<SegmentChanges> changes = segmentChanges(mesh, timeline, frames);
  REQUIRE(changes.size() == 1);
  const SegmentChanges& s = changes.front();
  CHECK(s.steps == 10);
  CHECK(s.maxPixelsFrame == 6);
  CHECK(s.maxRmsFrame == 6);
  CHECK(s.medianRms == Approx(1));
  CHECK(s.maxRms == Approx(20));
  CHECK(s.medianPixels == 20);   // a 1 px move of a 10 x 10 square: a column in, a column out
  CHECK(s.maxPixels == 200);     // moved past itself: all 100 out, 100 in
  CHECK(s.maxPixelsShare == Approx(2.0));
  REQUIRE(s.pixelSteps.size() == 10);
  CHECK(s.pixelSteps[5] == 200);  // the step onto frame 6
  CHECK(s.rmsSteps[5] == Approx(20));
  CHECK(s.rmsSteps[0] == Approx(1));
  CHECK(s.releases == std::vector<int>{6});
  CHECK(s.glues.empty());
  CHECK(s.minAreaRatio == Approx(1));  // every frame is the keys' square
}
