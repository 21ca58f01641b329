#include "core/error.h"
#include "render_fixtures.h"
#include "renderers/offscreen_renderer.h"
#include "vulkan_fixtures.h"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <cmath>

using namespace ib;
using namespace ib::render;
using ib::test::paintedImage;
using ib::test::pixel;
using ib::test::frameOf;
using ib::test::squareGrid;

namespace {

using Colour = std::array<uint8_t, 4>;

// Smooth, orientation-preserving warp about (128, 128): scale, rotate 20 degrees, bend.
Eigen::MatrixX2d warp(const Eigen::MatrixX2d& X) {
  Eigen::MatrixX2d x = X;
  const double c = std::cos(0.35), s = std::sin(0.35);
  for (int v = 0; v < X.rows(); ++v) {
    const double dx = 0.85 * (X(v, 0) - 128), dy = 0.75 * (X(v, 1) - 128);
    x.row(v) << 128 + c * dx - s * dy, 128 + s * dx + c * dy + 6 * std::sin(X(v, 0) / 40.0);
  }
  return x;
}

}  // namespace

TEST_CASE("renderer: a deformed mesh lands where its vertices say (marked vertices within 1 px)") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(9, 16, 16, 224, 1);  // cells of 28 px
  const Eigen::MatrixX2d X = mesh.keyPositions(0);
  const std::vector<int> marked = {10, 22, 40, 51, 66};   // interior vertices
  const std::vector<Colour> markers = {{255, 0, 0, 255}, {0, 180, 0, 255}, {0, 0, 255, 255}, {255, 0, 255, 255}, {0, 200, 200, 255}};
  // White drawing with a disc of radius 5 px in a marker colour around each marked vertex.
  const RenderMesh scene = renderMeshOf(mesh, {paintedImage(256, 256, [&](int px, int py) {
                                          for (size_t i = 0; i < marked.size(); ++i)
                                            if (std::hypot(px + 0.5 - X(marked[i], 0), py + 0.5 - X(marked[i], 1)) <= 5) return markers[i];
                                          return Colour{255, 255, 255, 255};
                                        })});
  OffscreenOptions options;
  options.width = options.height = 256;
  OffscreenRenderer renderer(context, scene, options);
  const Eigen::MatrixX2d x = warp(X);
  const RgbaImage image = renderer.render(frameOf(x, Eigen::VectorXd::Ones(1), {0, 0, 256, 256}));  // 1 drawing px = 1 pixel
  for (size_t i = 0; i < marked.size(); ++i) {
    // Centroid of the pixels within 60/255 of the marker colour (the disc's core, which blends
    // with nothing); pixel (i, j)'s centre is (i + 0.5, j + 0.5).
    double sx = 0, sy = 0, count = 0;
    for (int py = 0; py < 256; ++py)
      for (int px = 0; px < 256; ++px) {
        const std::array<double, 4> p = pixel(image, px, py);
        const bool nearest =
            std::pow(p[0] - markers[i][0], 2) + std::pow(p[1] - markers[i][1], 2) + std::pow(p[2] - markers[i][2], 2) < 60 * 60;
        if (nearest) {
          sx += px + 0.5;
          sy += py + 0.5;
          ++count;
        }
      }
    INFO("vertex " << marked[i] << " at (" << x(marked[i], 0) << ", " << x(marked[i], 1) << "), marker pixels " << count);
    REQUIRE(count > 20);
    CHECK(std::hypot(sx / count - x(marked[i], 0), sy / count - x(marked[i], 1)) < 1.0);
  }
  CHECK(context.validationMessages().empty());
}

TEST_CASE("renderer: overlays draw features, wireframe and onion skins") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(5, 8, 8, 48, 1);  // vertex 12 is the centre (32, 32)
  const RenderMesh scene = renderMeshOf(mesh, {paintedImage(64, 64, [](int, int) { return Colour{240, 240, 240, 255}; })}, {12});
  OffscreenOptions options;
  options.width = 256;
  options.height = 128;
  OffscreenRenderer renderer(context, scene, options);
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(1);
  FrameDraw plain = frameOf(x, one, {0, 0, 128, 64});  // 2 pixels per drawing pixel
  const RgbaImage before = renderer.render(plain);

  FrameDraw marked = plain;
  marked.overlays.features = true;
  marked.overlays.wireframe = true;
  const RgbaImage after = renderer.render(marked);

  {
    const std::array<double, 4> centre = pixel(after, 64, 64);  // the feature's square, 6 px wide
    CHECK(std::abs(centre[0] - 25.5) <= 3);
    CHECK(std::abs(centre[2] - 242.25) <= 3);
  }
  // Cell (8..20, 8..20) drawing px: its middle stays untouched, its vertical edge x = 20 darkens.
  CHECK(pixel(after, 28, 20)[0] == pixel(before, 28, 20)[0]);
  double darker = 0;
  for (int py = 20; py < 36; ++py) darker += pixel(before, 40, py)[0] - pixel(after, 40, py)[0];
  CHECK(darker / 16 > 40);

  // An onion skin 64 drawing px to the right, 30% opaque, where the frame itself is not.
  const Eigen::MatrixX2d shifted = x.rowwise() + Eigen::RowVector2d(60, 0);
  FrameDraw onion = plain;
  onion.onion.push_back({&shifted, one, {1.0f, 0.5f, 0.5f}, 0.3f});
  const RgbaImage skinned = renderer.render(onion);
  const std::array<double, 4> ghost = pixel(skinned, 2 * 92, 64);
  CHECK(std::abs(ghost[3] - 0.3 * 255) <= 2);
  CHECK(std::abs(ghost[0] - 240) <= 3);
  CHECK(std::abs(ghost[1] - 120) <= 3);
  CHECK(pixel(skinned, 64, 64)[3] == 255);  // the frame itself stays opaque over its skin
  CHECK(context.validationMessages().empty());
}

TEST_CASE("renderer: pipelined frames come back in submission order") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(3, 0, 0, 8, 1);
  const RenderMesh scene = renderMeshOf(mesh, {paintedImage(8, 8, [](int, int) { return Colour{0, 0, 0, 255}; })});
  OffscreenOptions options;
  options.width = 64;
  options.height = 16;
  options.framesInFlight = 2;
  OffscreenRenderer renderer(context, scene, options);
  const Eigen::MatrixX2d X = mesh.keyPositions(0);
  std::vector<Eigen::MatrixX2d> xs;
  for (int f = 0; f < 5; ++f) xs.push_back(X.rowwise() + Eigen::RowVector2d(10.0 * f, 4));
  for (const Eigen::MatrixX2d& x : xs) renderer.submit(frameOf(x, Eigen::VectorXd::Ones(1), {0, 0, 64, 16}));
  CHECK(renderer.pending() == 5);
  for (int f = 0; f < 5; ++f) {
    const RgbaImage image = renderer.take();
    double sum = 0, count = 0;
    for (int px = 0; px < 64; ++px) {
      sum += (px + 0.5) * pixel(image, px, 8)[3];
      count += pixel(image, px, 8)[3];
    }
    CHECK(sum / count == Approx(4 + 10.0 * f).margin(0.5));
  }
  CHECK(renderer.pending() == 0);
  CHECK_THROWS_AS(renderer.take(), std::logic_error);
  CHECK(context.validationMessages().empty());
}

TEST_CASE("renderer: bad options are input errors, bad frames the caller's errors, and both leave the renderer usable") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(3, 0, 0, 8, 2);
  const RgbaImage art = paintedImage(8, 8, [](int, int) { return Colour{9, 9, 9, 255}; });
  const RenderMesh scene = renderMeshOf(mesh, {art, art});
  CHECK_THROWS_AS(renderMeshOf(mesh, {art}), std::invalid_argument);
  OffscreenOptions bad;
  bad.width = 0;
  CHECK_THROWS_AS(OffscreenRenderer(context, scene, bad), InputError);
  OffscreenRenderer renderer(context, scene, OffscreenOptions{16, 16});
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  CHECK_THROWS_AS(renderer.render(frameOf(x, Eigen::VectorXd::Ones(3), {0, 0, 8, 8})), std::invalid_argument);
  CHECK_THROWS_AS(renderer.render(frameOf(x, (Eigen::VectorXd(2) << -0.5, 1.5).finished(), {0, 0, 8, 8})),
                  std::invalid_argument);
  CHECK_THROWS_AS(renderer.render(frameOf(x.topRows(3), (Eigen::VectorXd(2) << 0.5, 0.5).finished(), {0, 0, 8, 8})),
                  std::invalid_argument);
  const RgbaImage ok = renderer.render(frameOf(x, (Eigen::VectorXd(2) << 0.5, 0.5).finished(), {0, 0, 8, 8}));
  CHECK(pixel(ok, 8, 8)[3] == 255);
  CHECK(context.validationMessages().empty());
}
