#include "example_scenes.h"
#include "multimesh_builder.h"
#include "offscreen_renderer.h"
#include "render_fixtures.h"
#include "scene.h"

#include <catch2/catch.hpp>

using namespace ib;
using namespace ib::render;

namespace {

// Whether every pixel within `radius` of (x, y) in the drawing satisfies `alphaTest`.
template <typename Test>
bool neighbourhood(const RgbaImage& image, int x, int y, int radius, Test alphaTest) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int px = std::clamp(x + dx, 0, image.width - 1), py = std::clamp(y + dy, 0, image.height - 1);
      if (!alphaTest(image.at(px, py)[3])) return false;
    }
  return true;
}

}  // namespace

TEST_CASE("render: every bundled key renders as its drawing at its weight e_i (2 px from the outline)") {
  const vk::VulkanContext context = ib::test::validatedContext();
  int keysChecked = 0;
  for (const std::string& file : ::test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    const Scene scene = loadScene(file);
    const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
    const Multimesh& mesh = *built.multimesh;
    std::vector<RgbaImage> drawings;
    for (const KeySpec& key : scene.keys) drawings.push_back(readPng(key.drawing));
    const RenderMesh renderMesh = renderMeshOf(mesh, drawings);
    for (int k = 0; k < mesh.keyCount(); ++k) {
      const RgbaImage& drawing = drawings[k];
      OffscreenOptions options;
      options.width = drawing.width;
      options.height = drawing.height;
      OffscreenRenderer renderer(context, renderMesh, options);
      const Eigen::MatrixX2d x = mesh.keyPositions(k);
      FrameDraw frame;
      frame.positions = &x;
      frame.weights = Eigen::VectorXd::Unit(mesh.keyCount(), k);
      frame.view = {0, 0, double(drawing.width), double(drawing.height)};
      const RgbaImage image = renderer.render(frame);
      int inside = 0, outside = 0, wrongInside = 0, wrongOutside = 0;
      for (int py = 0; py < drawing.height; ++py)
        for (int px = 0; px < drawing.width; ++px) {
          const uint8_t* want = drawing.at(px, py);
          const uint8_t* got = image.at(px, py);
          if (neighbourhood(drawing, px, py, 2, [](uint8_t a) { return a == 255; })) {
            ++inside;
            bool same = got[3] >= 253;
            for (int c = 0; c < 3; ++c) same = same && std::abs(int(got[c]) - int(want[c])) <= 2;
            wrongInside += !same;
          } else if (neighbourhood(drawing, px, py, 2, [](uint8_t a) { return a == 0; })) {
            ++outside;
            wrongOutside += got[3] > 2;
          }
        }
      INFO(file << " key " << scene.keys[k].name << ": " << wrongInside << " of " << inside << " pixels inside, "
                << wrongOutside << " of " << outside << " outside differ");
      CHECK(inside > 100);
      CHECK(wrongInside == 0);
      CHECK(wrongOutside == 0);
      ++keysChecked;
    }
  }
  CHECK(keysChecked >= 10);
  CHECK(context.validationMessages().empty());
}
