#include "output/canvas.h"

#include <catch2/catch.hpp>

using namespace ib::render;

TEST_CASE("canvas: drawing, fit and WxH+X+Y parse as the three choices, anything else is refused with the forms") {
  CHECK(parseCanvas("drawing").kind == CanvasChoice::Kind::kDrawing);
  CHECK(parseCanvas("fit").kind == CanvasChoice::Kind::kFit);
  const CanvasChoice rect = parseCanvas("640x480-64+12");
  REQUIRE(rect.kind == CanvasChoice::Kind::kRect);
  CHECK(rect.rect.x0 == -64);
  CHECK(rect.rect.y0 == 12);
  CHECK(rect.rect.x1 == 576);
  CHECK(rect.rect.y1 == 492);
  for (const char* bad : {"", "Fit", "640x480", "640x480+1", "x480+0+0", "640x+0+0", "0x4+0+0", "640x480+0+0junk", "-5x5+0+0", "99999999x1+0+0"})
    CHECK_THROWS_WITH(parseCanvas(bad), Catch::Contains("WxH+X+Y"));
}

TEST_CASE("canvas: fit grows the animation's bounds by the margin onto whole pixels, and its picture is that many pixels") {
  CanvasChoice fit;
  fit.kind = CanvasChoice::Kind::kFit;
  const ViewBox drawing{0, 0, 128, 128};
  const ViewBox box = canvasBox(fit, drawing, {-10.3, 4.5, 140.2, 100});
  CHECK(box.x0 == -19);
  CHECK(box.y0 == -4);
  CHECK(box.x1 == 149);
  CHECK(box.y1 == 108);
  CHECK(canvasPixels(box) == std::array<int, 2>{168, 112});
  CHECK(canvasBox(CanvasChoice{}, drawing, {-10, -10, 500, 500}).x1 == 128);  // the drawings' canvas ignores the animation
}

TEST_CASE("canvas: frames reaching more than half a pixel past the box are counted, with runs of frames and the farthest reach") {
  const ViewBox box{0, 0, 100, 100};
  CanvasReach reach;
  Eigen::MatrixX2d inside(2, 2);
  inside << 1, 1, 99, 99;
  Eigen::MatrixX2d hair = inside;
  hair(1, 0) = 100.4;  // within half a pixel: not counted
  for (int f : {0, 1}) reach.add(f, inside, box);
  reach.add(2, hair, box);
  CHECK(reach.message(3).empty());
  Eigen::MatrixX2d out = inside;
  for (int f : {3, 4, 5, 9}) {
    out(0, 1) = -2.0 * f;  // up to 18 px above
    reach.add(f, out, box);
  }
  CHECK(reach.frames == std::vector<int>{3, 4, 5, 9});
  CHECK(reach.farthest == Approx(18));
  CHECK(reach.message(10) ==
        "4 of 10 frames reach past the canvas (frames 3-5, 9) by up to 18 drawing px, and are cut off there: --canvas fit "
        "shows the whole animation, or give a larger --canvas WxH+X+Y");
}
