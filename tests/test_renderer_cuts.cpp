#include "core/error.h"
#include "render_fixtures.h"
#include "renderers/offscreen_renderer.h"
#include "vulkan_fixtures.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

using namespace ib;
using namespace ib::render;
using namespace ib::test;

TEST_CASE("renderer: a glued cut shows no seam where another key draws it open, an open cut stays open") {
  const vk::VulkanContext context = test::validatedContext();
  const CutSquare cut = cutSquare();
  OffscreenOptions target;
  target.width = 192;
  target.height = 128;
  OffscreenRenderer renderer(context, renderMeshOf(cut.mesh, cutSquareArtwork()), target);
  const ViewBox view{0, 0, 48, 32};  // 4 target pixels per drawing pixel
  const Eigen::VectorXd half = Eigen::Vector2d(0.5, 0.5);

  // Glued within a tenth of a drawing pixel, as the solver leaves a cohesive zone: opaque across
  // the cut, where a plain blend of the two keys' alpha would leave a line at 3/4 opacity.
  for (double gap : {0.0, 0.1}) {
    const Eigen::MatrixX2d x = shiftedRight(cut.mesh.keyPositions(0), cut.right, gap);
    const RgbaImage image = renderer.render(frameOf(x, half, view));
    double lowest = 255;
    for (int py = 8; py < 120; ++py)
      for (int px = 40; px < 152; ++px) lowest = std::min(lowest, pixel(image, px, py)[3]);
    INFO("gap " << gap << " drawing pixels: lowest alpha inside the square " << lowest);
    CHECK(lowest >= 253);
  }

  // Open by 8 drawing pixels: the cut shows as a gap, transparent in its middle, and each half
  // keeps the blend of the two keys' colours.
  const Eigen::MatrixX2d open = cut.mesh.keyPositions(1);
  const RgbaImage image = renderer.render(frameOf(open, half, view));
  CHECK(pixel(image, 112, 64)[3] <= 2);
  for (int px : {64, 160}) {
    const std::array<double, 4> p = pixel(image, px, 64);
    CHECK(p[3] >= 253);
    CHECK(std::abs(p[0] - 0.5 * (20 + 240)) <= 3);
    CHECK(std::abs(p[1] - 0.5 * (150 + 120)) <= 3);
  }
  CHECK(context.validationMessages().empty());
}
