#include "core/plane_geometry.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "output/key_fidelity.h"
#include "pipeline/artwork_sampling.h"
#include "render_fixtures.h"
#include "renderers/offscreen_renderer.h"
#include "scene/scene.h"
#include "testkit/example_scenes.h"
#include "testkit/shared_results.h"
#include "vulkan_fixtures.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <string>

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

// A bundled scene's multimesh as the front ends build it (Comesh Optimization on, no cache; shared
// by this program's test cases, test::bundledMultimesh) with its drawings, and one frame's target
// for key k.
struct BundledScene {
  Scene scene;
  Multimesh mesh;
  std::vector<RgbaImage> drawings;  // [key]

  explicit BundledScene(const std::string& file)
      : scene(loadScene(file)),
        mesh(*::test::bundledMultimesh(scene, std::filesystem::path(file).parent_path().filename().string()).multimesh) {
    for (const KeySpec& key : scene.keys) drawings.push_back(readPng(key.drawing));
  }
  // Key k's drawing size, showing its drawing's rectangle.
  OffscreenOptions target(int k) const {
    OffscreenOptions options;
    options.width = drawings[k].width;
    options.height = drawings[k].height;
    return options;
  }
  FrameDraw frame(int k, const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const {
    FrameDraw out;
    out.positions = &x;
    out.weights = w;
    out.view = {0, 0, double(drawings[k].width), double(drawings[k].height)};
    return out;
  }
};

}  // namespace

TEST_CASE("render: every bundled key renders as its drawing at its weight e_i, every pixel within 2/255 at its size and at twice it") {
  const vk::VulkanContext context = ib::test::validatedContext();
  int keysChecked = 0;
  for (const std::string& file : ::test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    const BundledScene bundled(file);
    const Multimesh& mesh = bundled.mesh;
    const bool nearest = nearestSampling(bundled.scene, bundled.drawings);
    RenderMesh renderMesh = renderMeshOf(mesh, bundled.drawings);
    if (!bundled.scene.cutInk) renderMesh.inks = {};
    for (int scale : {1, 2}) {
      OffscreenOptions target = bundled.target(0);
      target.width *= scale;
      target.height *= scale;
      OffscreenRenderer renderer(context, renderMesh, target);
      for (int k = 0; k < mesh.keyCount(); ++k) {
        const Eigen::MatrixX2d x = mesh.keyPositions(k);
        FrameDraw draw = bundled.frame(0, x, Eigen::VectorXd::Unit(mesh.keyCount(), k));
        draw.sampling = nearest ? Sampling::kNearest : Sampling::kLinear;
        const KeyFidelity fidelity = keyFidelity(renderer.render(draw), bundled.drawings[k], scale, nearest);
        INFO(file << " key " << bundled.scene.keys[k].name << " at " << scale << "x: " << fidelity.over << " of " << fidelity.pixels
                  << " pixels off by more than 2/255, the most " << fidelity.worst << " at (" << fidelity.worstX << ", "
                  << fidelity.worstY << ")");
        CHECK(fidelity.over == 0);
        ++keysChecked;
      }
    }
  }
  CHECK(keysChecked >= 20);
  CHECK(context.validationMessages().empty());
}

TEST_CASE("render: every bundled cut glued in an inbetween shows no seam (alpha >= 240 within 4 px of the cut, 6 px from its ends, 3 px inside the mesh)") {
  const vk::VulkanContext context = ib::test::validatedContext();
  int inbetweensChecked = 0;
  for (const std::string& file : ::test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    const BundledScene bundled(file);
    const Scene& scene = bundled.scene;
    const Multimesh& mesh = bundled.mesh;
    const int m = mesh.keyCount();
    std::vector<RgbaImage> blank;  // opaque white: what the mesh covers
    for (const RgbaImage& d : bundled.drawings)
      blank.push_back(ib::test::paintedImage(d.width, d.height, [](int, int) {
        return std::array<uint8_t, 4>{255, 255, 255, 255};
      }));
    const RenderMesh art = renderMeshOf(mesh, bundled.drawings), coverage = renderMeshOf(mesh, blank);
    Interpolator interpolator(mesh, scene.interpolation, SolverOptions{});
    for (int k = 0; k < m; ++k) {
      if (mesh.cohesivePairs(k).empty()) continue;
      // Key k, whose cuts are glued, with as much of the keys that draw them open as keeps them
      // glued (gaps under a quarter pixel): the first of w_k = 0.5, 0.6, .., 0.9, 0.95, 0.99 that
      // does. Examples whose cuts let go at once (a cohesive threshold tau of 1e-7 makes a cell
      // split as soon as it starts to move) have no glued inbetween to look at.
      const Eigen::MatrixX2d glued = mesh.keyPositions(k);
      // The sides of the cuts key k draws (a cut open in key k is apart there, and stays apart).
      std::vector<char> drawn(static_cast<size_t>(mesh.vertexCount()), 0);
      for (const CohesivePair& p : mesh.cohesivePairs(k)) drawn[p.a] = drawn[p.b] = drawn[p.c] = drawn[p.d] = 1;
      Eigen::VectorXd w;
      Eigen::MatrixX2d x;
      double widest = INFINITY;
      for (double wk : {0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99}) {
        w = Eigen::VectorXd::Constant(m, (1 - wk) / (m - 1));
        w[k] = wk;
        x = interpolator.solve(w, &glued).x;  // from key k, as a stream leaving it would
        widest = 0;
        for (const Edge& e : art.cutSides.partners)
          if (drawn[e[0]] && drawn[e[1]]) widest = std::max(widest, (x.row(e[0]) - x.row(e[1])).norm());
        if (widest < 0.25) break;
      }
      INFO(file << " at w = " << w.transpose() << ": cut gaps up to " << widest << " px");
      if (widest >= 0.25) {
        // Only a scene that asks for it lets go at once: the paper's timing with a low tau.
        CHECK(scene.interpolation.cohesive.timing == CutTiming::kTau);
        CHECK(scene.interpolation.cohesive.tau <= 1e-5);
        continue;
      }
      const RgbaImage image = OffscreenRenderer(context, art, bundled.target(k)).render(bundled.frame(k, x, w));
      const RgbaImage covered = OffscreenRenderer(context, coverage, bundled.target(k)).render(bundled.frame(k, x, w));
      int inside = 0, seeThrough = 0, lowest = 255;
      // The seam: pixels within 4 px of key k's cut sides (its cohesive pairs' edges at x), but
      // not within 6 px of where a side ends. Elsewhere, and where a cut meets the outline (a split
      // drawn into a V between two strokes, chinese-character's), pixels that the mesh covers and
      // the drawing leaves partly transparent are the silhouette's matter (its chord across a
      // concave corner of the outline), not a seam.
      std::vector<std::array<Eigen::Vector2d, 2>> sides;
      std::map<int, int> degree;  // [vertex]: cut-side edges at it; 1 at a side's end
      for (const CohesivePair& p : mesh.cohesivePairs(k))
        for (const auto& [u, v] : {std::pair{p.a, p.b}, std::pair{p.c, p.d}}) {
          sides.push_back({x.row(u).transpose(), x.row(v).transpose()});
          ++degree[u], ++degree[v];
        }
      std::vector<Eigen::Vector2d> ends;
      for (const auto& [v, count] : degree)
        if (count == 1) ends.push_back(x.row(v).transpose());
      const auto nearSeam = [&](int px, int py) {
        const Eigen::Vector2d q(px + 0.5, py + 0.5);
        for (const Eigen::Vector2d& e : ends)
          if ((e - q).norm() <= 6) return false;
        for (const auto& [a, b] : sides)
          if ((a + closestParameter(a, b, q) * (b - a) - q).norm() <= 4) return true;
        return false;
      };
      for (int py = 0; py < image.height; ++py)
        for (int px = 0; px < image.width; ++px)
          if (neighbourhood(covered, px, py, 3, [](uint8_t a) { return a == 255; }) && nearSeam(px, py)) {
            ++inside;
            seeThrough += image.at(px, py)[3] < 240;  // a plain blend leaves 171-232 here
            lowest = std::min<int>(lowest, image.at(px, py)[3]);
          }
      INFO(seeThrough << " of " << inside << " pixels 3 px inside the mesh and within 4 px of the cut under alpha 240, lowest "
                      << lowest);
      CHECK(inside > 100);
      CHECK(seeThrough == 0);
      ++inbetweensChecked;
    }
  }
  CHECK(inbetweensChecked >= 3);
  CHECK(context.validationMessages().empty());
}
