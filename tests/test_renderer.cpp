#include "core/error.h"
#include "render_fixtures.h"
#include "renderers/offscreen_renderer.h"
#include "vulkan_fixtures.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ib;
using namespace ib::render;
using ib::test::coveredArea;
using ib::test::paintedImage;
using ib::test::pixel;
using ib::test::frameOf;
using ib::test::squareGrid;

namespace {

using Colour = std::array<uint8_t, 4>;

// Drawing 64 x 64: four opaque quadrants (red, green, blue, yellow).
Colour quadrant(int x, int y) {
  if (y < 32) return x < 32 ? Colour{220, 30, 40, 255} : Colour{30, 200, 60, 255};
  return x < 32 ? Colour{40, 60, 210, 255} : Colour{230, 210, 20, 255};
}

void requireColour(const RgbaImage& image, int x, int y, const std::array<double, 4>& expected, double tolerance) {
  const std::array<double, 4> got = pixel(image, x, y);
  INFO("pixel (" << x << ", " << y << "): got " << got[0] << " " << got[1] << " " << got[2] << " " << got[3] << ", expected "
                 << expected[0] << " " << expected[1] << " " << expected[2] << " " << expected[3]);
  for (int c = 0; c < 4; ++c) CHECK(std::abs(got[c] - expected[c]) <= tolerance);
}

Eigen::VectorXd weights2(double a, double b) { return (Eigen::VectorXd(2) << a, b).finished(); }

OffscreenOptions squareTarget(int size) {
  OffscreenOptions options;
  options.width = options.height = size;
  return options;
}

}  // namespace

TEST_CASE("renderer: a textured square shows its texture within 2/255 and covers its area within 1%") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(5, 8, 8, 48, 2);
  // Key 0 draws the quadrants where its mesh is, [8, 56)^2, and nothing around them, as a traced
  // drawing does (at and near a key its drawing shows as drawn, also past the mesh's edge).
  const auto square = [](int px, int py) { return px >= 8 && px < 56 && py >= 8 && py < 56 ? quadrant(px, py) : Colour{0, 0, 0, 0}; };
  const RenderMesh scene = renderMeshOf(mesh, {paintedImage(64, 64, square), paintedImage(64, 64, [](int, int) {
                                                 return Colour{255, 255, 255, 255};
                                               })});
  OffscreenRenderer renderer(context, scene, squareTarget(128));
  CHECK(renderer.samples() == VK_SAMPLE_COUNT_4_BIT);
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  // Key 1 has weight 0: only key 0's artwork shows. The view doubles drawing pixels.
  const RgbaImage image = renderer.render(frameOf(x, weights2(1, 0), {0, 0, 64, 64}));
  requireColour(image, 30, 30, {220, 30, 40, 255}, 2);
  requireColour(image, 90, 30, {30, 200, 60, 255}, 2);
  requireColour(image, 30, 90, {40, 60, 210, 255}, 2);
  requireColour(image, 90, 90, {230, 210, 20, 255}, 2);
  CHECK(pixel(image, 4, 4)[3] == 0);  // the transparent background outside the square
  CHECK(coveredArea(image) == Approx(96.0 * 96.0).epsilon(0.01));

  // Rotated by 30 degrees: edges cross pixels at every fraction, and MSAA still gets the area right.
  Eigen::MatrixX2d rotated = x;
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (int v = 0; v < x.rows(); ++v) {
    const double dx = x(v, 0) - 32, dy = x(v, 1) - 32;
    rotated.row(v) << 32 + c * dx - s * dy, 32 + s * dx + c * dy;
  }
  const RgbaImage turned = renderer.render(frameOf(rotated, weights2(1, 0), {0, 0, 64, 64}));
  CHECK(coveredArea(turned) == Approx(96.0 * 96.0).epsilon(0.01));
  CHECK(context.validationMessages().empty());
}

TEST_CASE("renderer: two keys' artwork blends by the weights") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(4, 4, 4, 24, 2);
  const RenderMesh scene = renderMeshOf(mesh, {paintedImage(32, 32, [](int, int) { return Colour{200, 40, 40, 255}; }),
                                               paintedImage(32, 32, [](int, int) { return Colour{40, 80, 200, 255}; })});
  OffscreenRenderer renderer(context, scene, squareTarget(64));
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  for (double w : {0.5, 0.25, 0.9}) {
    const RgbaImage image = renderer.render(frameOf(x, weights2(w, 1 - w), {0, 0, 32, 32}));
    INFO("w = (" << w << ", " << 1 - w << ")");
    requireColour(image, 32, 32, {200 * w + 40 * (1 - w), 40 * w + 80 * (1 - w), 40 * w + 200 * (1 - w), 255}, 2);
  }
  CHECK(context.validationMessages().empty());
}

TEST_CASE("renderer: three and five keys in play blend by their weights (every shader variant)") {
  const vk::VulkanContext context = test::validatedContext();
  const std::vector<Colour> colours = {{250, 0, 0, 255}, {0, 250, 0, 255}, {0, 0, 250, 255}, {250, 250, 0, 255}, {0, 250, 250, 255}};
  const Multimesh mesh = squareGrid(3, 2, 2, 12, 5);
  std::vector<RgbaImage> art;
  for (const Colour& c : colours) art.push_back(paintedImage(16, 16, [c](int, int) { return c; }));
  OffscreenRenderer renderer(context, renderMeshOf(mesh, art), squareTarget(16));
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  for (const Eigen::VectorXd& w : {Eigen::VectorXd((Eigen::VectorXd(5) << 0.2, 0.3, 0.5, 0, 0).finished()),
                                   Eigen::VectorXd((Eigen::VectorXd(5) << 0.1, 0.2, 0.3, 0.25, 0.15).finished())}) {
    std::array<double, 4> expected{0, 0, 0, 255};
    for (int k = 0; k < 5; ++k)
      for (int c = 0; c < 3; ++c) expected[c] += w[k] * colours[k][c];
    INFO("w = " << w.transpose());
    requireColour(renderer.render(frameOf(x, w, {0, 0, 16, 16})), 8, 8, expected, 2);
  }
  CHECK(context.validationMessages().empty());
}

TEST_CASE("renderer: semi-transparent line art keeps its colour at its edges (premultiplied alpha)") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(3, 0, 0, 32, 1);
  // Left half opaque dark blue, right half transparent white (a cheap PNG's invisible colour).
  const RenderMesh scene = renderMeshOf(mesh, {paintedImage(32, 32, [](int x, int) {
                                          return x < 16 ? Colour{20, 40, 160, 255} : Colour{255, 255, 255, 0};
                                        })});
  OffscreenRenderer renderer(context, scene, squareTarget(128));
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  const RgbaImage image = renderer.render(frameOf(x, Eigen::VectorXd::Ones(1), {0, 0, 32, 32}));
  // Across the edge the colour stays dark blue while alpha falls: no white fringe.
  for (int px = 56; px < 72; ++px) {
    const std::array<double, 4> p = pixel(image, px, 64);
    if (p[3] < 8) continue;  // too transparent to carry a colour after 8-bit rounding
    INFO("pixel " << px << " alpha " << p[3]);
    CHECK(std::abs(p[0] - 20) <= 255.0 / p[3] + 1);
    CHECK(std::abs(p[2] - 160) <= 255.0 / p[3] + 1);
  }
  CHECK(context.validationMessages().empty());
}

TEST_CASE("renderer: artwork drawn at a quarter of its size is filtered, not aliased (mipmaps)") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(3, 0, 0, 256, 1);
  // One-pixel black and white checkerboard: point sampling it at 1/4 scale gives black or white.
  const RenderMesh scene = renderMeshOf(mesh, {paintedImage(256, 256, [](int x, int y) {
                                          const uint8_t v = (x + y) % 2 ? 255 : 0;
                                          return Colour{v, v, v, 255};
                                        })});
  OffscreenRenderer renderer(context, scene, squareTarget(64));
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  // 4.3 texels per pixel: pixel centres fall at every fraction of a texel.
  const RgbaImage image = renderer.render(frameOf(x, Eigen::VectorXd::Ones(1), {0, 0, 275.2, 275.2}));
  double lowest = 255, highest = 0;
  for (int py = 4; py < 56; ++py)
    for (int px = 4; px < 56; ++px) {
      lowest = std::min(lowest, pixel(image, px, py)[0]);
      highest = std::max(highest, pixel(image, px, py)[0]);
    }
  INFO("grey between " << lowest << " and " << highest);
  CHECK(lowest > 127.5 - 8);
  CHECK(highest < 127.5 + 8);
  CHECK(context.validationMessages().empty());
}

TEST_CASE("renderer: nearest sampling keeps magnified texels hard, linear blends them, switched per frame") {
  const vk::VulkanContext context = test::validatedContext();
  const Multimesh mesh = squareGrid(3, 0, 0, 4, 1);
  // A 4 x 4 checkerboard of two opaque colours, every channel different, drawn 16x on a 64 x 64 target.
  const Colour a{230, 40, 30, 255}, b{20, 90, 220, 255};
  const RenderMesh scene = renderMeshOf(mesh, {paintedImage(4, 4, [&](int x, int y) { return (x + y) % 2 ? b : a; })});
  OffscreenRenderer renderer(context, scene, squareTarget(64));
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  FrameDraw frame = frameOf(x, Eigen::VectorXd::Ones(1), {0, 0, 4, 4});
  // The larger of a pixel's distances (any channel, in 1/255) to colour a and to colour b.
  const auto distances = [&](const RgbaImage& image, int px, int py) {
    const std::array<double, 4> p = pixel(image, px, py);
    std::array<double, 2> d{0, 0};
    for (int c = 0; c < 4; ++c) {
      d[0] = std::max(d[0], std::abs(p[c] - a[c]));
      d[1] = std::max(d[1], std::abs(p[c] - b[c]));
    }
    return d;
  };
  for (const Sampling sampling : {Sampling::kNearest, Sampling::kLinear, Sampling::kNearest}) {
    frame.sampling = sampling;
    const RgbaImage image = renderer.render(frame);
    int exact = 0, intermediate = 0, checked = 0;
    for (int py = 0; py < 64; ++py)
      for (int px = 0; px < 64; ++px) {
        if (px % 16 == 0 || px % 16 == 15 || py % 16 == 0 || py % 16 == 15) continue;  // beside a texel edge
        ++checked;
        const std::array<double, 2> d = distances(image, px, py);
        if (std::min(d[0], d[1]) <= 1) ++exact;
        if (std::min(d[0], d[1]) > 16) ++intermediate;
      }
    INFO((sampling == Sampling::kNearest ? "nearest" : "linear") << ": " << exact << " of " << checked
                                                                 << " pixels exact, " << intermediate << " intermediate");
    if (sampling == Sampling::kNearest) {
      CHECK(exact == checked);
    } else {
      CHECK(intermediate > checked / 2);
      // Just left of the edge between texels 1 and 2 of row 0, the two colours half and half (within 10%).
      const std::array<double, 4> p = pixel(image, 31, 8);
      for (int c = 0; c < 3; ++c) CHECK(std::abs(p[c] - 0.5 * (a[c] + b[c])) <= 0.1 * std::abs(a[c] - b[c]));
    }
  }
  CHECK(context.validationMessages().empty());
}
