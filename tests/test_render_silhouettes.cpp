// Silhouettes (docs/rendering.md, "Silhouettes"): every rendered frame's opacity is the mesh's
// coverage, never the keys' partly transparent rims blended into its interior.
#include "animation/frame_stream.h"
#include "core/plane_geometry.h"
#include "interpolation/interpolator.h"
#include "pipeline/scene_frames.h"
#include "multimesh/multimesh.h"
#include "render_fixtures.h"
#include "renderers/offscreen_renderer.h"
#include "scene/scene.h"
#include "testkit/example_scenes.h"
#include "testkit/shared_results.h"
#include "vulkan_fixtures.h"

#include <catch2/catch.hpp>
#include <filesystem>

using namespace ib;
using namespace ib::render;

namespace {

constexpr int kTarget = 256;  // px: frames are rendered at most this wide or high
// Opaque enough to hide what lies behind (94%): 8-bit blends of opaque texels, and glued cuts'
// welds (docs/rendering.md, "Glued cuts"), land a few steps under 255.
constexpr uint8_t kOpaque = 240;

// Whether every pixel of `image` within 1.5 px of (x, y) (the 3 x 3 block) has alpha `a`.
bool allWithin(const RgbaImage& image, int x, int y, uint8_t a) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int px = std::clamp(x + dx, 0, image.width - 1), py = std::clamp(y + dy, 0, image.height - 1);
      if (image.at(px, py)[3] != a) return false;
    }
  return true;
}

// Pixels within `radius` (target px) of an outline edge of the mesh at x (drawing px, scaled by
// `scale`): where two pieces touch (circles-in-circles' contacts), the coverage is whole across
// their outlines but each piece's silhouette has its edge there, so those pixels are edge, not
// inside. Cut sides are not outline: a glued cut is inside.
std::vector<char> nearOutline(int width, int height, const std::vector<Edge>& outline, const Eigen::MatrixX2d& x,
                              double scale, double radius) {
  std::vector<char> near(static_cast<size_t>(width) * height, 0);
  for (const Edge& e : outline) {
    const Eigen::Vector2d a = x.row(e[0]).transpose() * scale, b = x.row(e[1]).transpose() * scale;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - radius)));
    const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + radius)));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - radius)));
    const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + radius)));
    for (int py = y0; py <= y1; ++py)
      for (int px = x0; px <= x1; ++px) {
        const Eigen::Vector2d q(px + 0.5, py + 0.5);
        if ((a + closestParameter(a, b, q) * (b - a) - q).norm() <= radius) near[static_cast<size_t>(py) * width + px] = 1;
      }
  }
  return near;
}

}  // namespace

TEST_CASE("render: every frame of every bundled scene away from its keys is opaque more than 1.5 px inside the mesh's silhouette, transparent more than 1.5 px outside, antialiased between") {
  const vk::VulkanContext context = ib::test::validatedContext();
  int framesChecked = 0;
  for (const std::string& file : ::test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    const Scene scene = loadScene(file);
    const std::shared_ptr<const Multimesh> built =
        ::test::bundledMultimesh(scene, std::filesystem::path(file).parent_path().filename().string()).multimesh;
    const Multimesh& mesh = *built;
    std::vector<RgbaImage> drawings, blank;  // blank: opaque white, whose render is the mesh's coverage
    for (const KeySpec& key : scene.keys) {
      drawings.push_back(readPng(key.drawing));
      blank.push_back(ib::test::paintedImage(drawings.back().width, drawings.back().height,
                                             [](int, int) { return std::array<uint8_t, 4>{255, 255, 255, 255}; }));
    }
    const RenderMesh art = renderMeshOf(mesh, drawings), coverage = renderMeshOf(mesh, blank);
    const double width = drawings[0].width, height = drawings[0].height, scale = kTarget / std::max(width, height);
    OffscreenOptions target;
    target.width = static_cast<int>(std::round(width * scale));
    target.height = static_cast<int>(std::round(height * scale));
    OffscreenRenderer artRenderer(context, art, target), coverageRenderer(context, coverage, target);
    std::vector<char> onCut(static_cast<size_t>(mesh.vertexCount()), 0);
    for (const Edge& e : art.cutSides.partners) onCut[e[0]] = onCut[e[1]] = 1;
    for (const CohesivePair& p : art.cutSides.pairs) onCut[p.a] = onCut[p.b] = onCut[p.c] = onCut[p.d] = 1;
    std::vector<Edge> outline;
    for (const Edge& e : mesh.boundaryEdges())
      if (!onCut[e[0]] || !onCut[e[1]]) outline.push_back(e);
    FrameStream stream = sceneFrameStream(scene, mesh);
    int worstFrame = -1, worstInside = 0, worstOutside = 0, rims = 0, lowest = 255;
    Eigen::Vector2d lowestAt(0, 0);
    while (!stream.done()) {
      const AnimationFrame frame = stream.next();
      // At and near a key the frame is its drawing, gaps and soft edges as drawn (test_render_assets.cpp).
      if (keyness(frame.weights) > 0) continue;
      FrameDraw draw = ib::test::frameOf(frame.x, frame.weights, {0, 0, width, height});
      draw.heldPairs = &frame.heldPairs;
      const RgbaImage image = artRenderer.render(draw), covered = coverageRenderer.render(draw);
      const std::vector<char> edge = nearOutline(image.width, image.height, outline, frame.x, scale, 1.5);
      int seeThrough = 0, spilled = 0, rim = 0, low = 255;
      Eigen::Vector2d lowAt(0, 0);
      for (int py = 0; py < image.height; ++py)
        for (int px = 0; px < image.width; ++px) {
          const uint8_t a = image.at(px, py)[3];
          if (allWithin(covered, px, py, 255) && !edge[static_cast<size_t>(py) * image.width + px]) {
            seeThrough += a < kOpaque;
            if (a < low) {
              low = a;
              lowAt = Eigen::Vector2d(px + 0.5, py + 0.5) / scale;
            }
          }
          else if (allWithin(covered, px, py, 0)) spilled += a > 0;
          else rim += a > 0 && a < 255;
        }
      rims += rim;
      if (seeThrough + spilled > worstInside + worstOutside) {
        worstFrame = frame.index;
        worstInside = seeThrough;
        worstOutside = spilled;
        lowest = low;
        lowestAt = lowAt;
      }
      ++framesChecked;
    }
    INFO(file << ": frame " << worstFrame << " has " << worstInside << " pixels under alpha " << int(kOpaque) << " more than 1.5 px inside the mesh, "
              << worstOutside << " drawn more than 1.5 px outside it; the lowest alpha inside " << lowest << " at drawing px ("
              << lowestAt.x() << ", " << lowestAt.y() << ")");
    CHECK(worstInside == 0);
    CHECK(worstOutside == 0);
    CHECK(rims > 0);  // the edge is antialiased
  }
  CHECK(framesChecked >= 200);
  CHECK(context.validationMessages().empty());
}
