// The edge length that follows the drawing, the size guard, and the scene's "sampling" field
// (meshing/mesh_size.h, pipeline/artwork_sampling.h, docs/drawings-to-multimesh.md "Edge length").
#include "core/error.h"
#include "meshing/mesh_size.h"
#include "meshing/multimesh_builder.h"
#include "meshing/outline_fit.h"
#include "pipeline/scene_multimesh.h"
#include "pipeline/artwork_sampling.h"
#include "scene/scene.h"
#include "sprites.h"
#include "testkit/drawings.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>

using namespace ib;
namespace fs = std::filesystem;

namespace {

// A two-key scene in a fresh folder: key "a" is `a`, key "b" is `b`; `fields` are extra
// top-level JSON fields (with a trailing comma).
Scene writeScene(const std::string& folder, const RgbaImage& a, const RgbaImage& b, const std::string& fields = "") {
  const std::string dir = test::scratchDirectory(folder);
  writePng((fs::path(dir) / "a.png").string(), a);
  writePng((fs::path(dir) / "b.png").string(), b);
  const std::string path = (fs::path(dir) / "scene.json").string();
  std::ofstream(path) << "{\"version\": 1, " << fields
                      << "\"keys\": [{\"name\": \"a\", \"drawing\": \"a.png\"}, {\"name\": \"b\", \"drawing\": \"b.png\"}]}";
  return loadScene(path);
}

Scene birdScene(int size, const std::string& fields = "") {
  return writeScene("mesh-size-bird" + std::to_string(size), test::birdSprite(size), test::birdSprite(size, 6), fields);
}

double edgeCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
}

// Share of the drawing's drawn pixels (alpha >= 128) whose centre no triangle of key k covers.
double lostShare(const Multimesh& mesh, int k, const RgbaImage& drawing) {
  const Eigen::MatrixX2d& X = mesh.keyPositions(k);
  std::vector<char> covered(static_cast<size_t>(drawing.width) * drawing.height, 0);
  for (const Triangle& t : mesh.triangles()) {
    const Eigen::Vector2d a = X.row(t[0]), b = X.row(t[1]), c = X.row(t[2]);
    const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()})))), x1 = std::min(drawing.width - 1, int(std::max({a.x(), b.x(), c.x()})));
    const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()})))), y1 = std::min(drawing.height - 1, int(std::max({a.y(), b.y(), c.y()})));
    const double s = edgeCross(a, b, c);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2d p(x + 0.5, y + 0.5);
        if (s * edgeCross(a, b, p) >= 0 && s * edgeCross(b, c, p) >= 0 && s * edgeCross(c, a, p) >= 0)
          covered[static_cast<size_t>(y) * drawing.width + x] = 1;
      }
  }
  int drawn = 0, lost = 0;
  for (int y = 0; y < drawing.height; ++y)
    for (int x = 0; x < drawing.width; ++x)
      if (drawing.at(x, y)[3] >= 128) {
        ++drawn;
        lost += !covered[static_cast<size_t>(y) * drawing.width + x];
      }
  return double(lost) / drawn;
}

std::vector<Outline> traced(const RgbaImage& image) {
  const TracingOptions tracing;  // the scene's defaults
  return traceOutlines(shapeMask(image, tracing, {}, "a.png"), tracing, "a.png");
}

}  // namespace

TEST_CASE("mesh size: the default edge length is sqrt(mean key area) / 16, clamped to [1, 8] px") {
  struct Case {
    int size;
    double lo, hi;  // px: the expected default
  };
  // The bird's shape is about 0.23 of its canvas: sqrt(area) is about 0.48 of the canvas side.
  for (const Case c : {Case{32, 1, 1}, Case{64, 1.7, 2.1}, Case{96, 2.6, 3.1}, Case{128, 3.5, 4.2}, Case{512, 8, 8}}) {
    const std::vector<std::vector<Outline>> outlines = {traced(test::birdSprite(c.size)), traced(test::birdSprite(c.size, 6))};
    const double area = (tracedArea(outlines[0]) + tracedArea(outlines[1])) / 2;
    INFO(c.size << " px, area " << area);
    const double e = defaultEdgeLength(outlines);
    CHECK(e == Approx(std::clamp(std::sqrt(area) / kEdgeDivisions, 1.0, 8.0)));
    CHECK(e >= c.lo - 1e-9);
    CHECK(e <= c.hi + 1e-9);
  }
}

TEST_CASE("mesh size: a 64 px sprite meshed at the default edge length keeps its beak and toes, and at 8 px its boundary still follows them with far fewer vertices") {
  const RgbaImage drawing = test::birdSprite(64);
  const Scene scene = birdScene(64);
  REQUIRE(scene.edgeLength == 0);  // absent: follow the drawing
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  CHECK(built.edgeLength == Approx(1.9).margin(0.2));
  CHECK(built.multimesh->vertexCount() >= 400);
  const double lostDefault = lostShare(*built.multimesh, 0, drawing);

  Scene coarse = scene;
  coarse.edgeLength = 8;  // the default before the rule: an explicit edge length wins
  const BuiltScene old = buildMultimesh(coarse, MultimeshBuildOptions{});
  CHECK(old.edgeLength == 8);
  CHECK(old.multimesh->vertexCount() < built.multimesh->vertexCount() / 2);
  // Before the boundary followed the drawings (docs/drawings-to-multimesh.md, "Following the
  // drawings"), 8 px lost the beak and toes (over 5% of the pixels); the knots where the outline
  // curves keep them at any edge length.
  const double lostCoarse = lostShare(*old.multimesh, 0, drawing);
  INFO("lost at the default " << lostDefault << ", at 8 px " << lostCoarse);
  CHECK(lostDefault < 0.04);
  CHECK(lostCoarse < 0.04);
}

TEST_CASE("mesh size: the bird sprite at 32-128 px, meshed and optimized at the defaults, follows every key's traced outline within 0.5 px and loses at most 1.5% of its pixels from 64 px") {
  for (const int size : {32, 64, 96, 128}) {
    const Scene scene = birdScene(size);
    SceneMultimeshOptions options;
    options.useCache = false;
    const SceneMultimesh built = sceneMultimesh(scene, options);
    const std::vector<OutlineFit> fits = outlineFits(*built.multimesh, built.shapes);
    for (int k = 0; k < 2; ++k) {
      const double lost = lostShare(*built.multimesh, k, test::birdSprite(size, 6.0 * k));
      INFO(size << " px, key " << k << ": mesh boundary up to " << fits[k].largest << " px from the outline at ("
                << fits[k].where.transpose() << "), " << 100 * lost << "% of the drawn pixels lost, "
                << built.multimesh->vertexCount() << " vertices");
      CHECK(fits[k].largest < 0.5);
      if (size >= 64) CHECK(lost <= 0.015);  // at 32 px the 0.7 px legs are under the tracing's speck size
    }
  }
}

TEST_CASE("mesh size: an explicit edge_length in the scene wins over the default") {
  const Scene scene = birdScene(96, "\"edge_length\": 5, ");
  CHECK(scene.edgeLength == 5);
  CHECK(buildMultimesh(scene, MultimeshBuildOptions{}).edgeLength == 5);
}

TEST_CASE("mesh size: the vertex estimate is within 15% of real builds") {
  const RgbaImage disc = test::drawShape(256, 256, test::disc(128, 128, 100), 200, 40, 40);
  struct Case {
    RgbaImage image;
    double edgeLength;
  };
  for (const Case& c : {Case{disc, 3}, Case{disc, 6}, Case{test::birdSprite(96), 2}, Case{test::birdSprite(192), 4}}) {
    const Scene scene = writeScene("mesh-size-estimate", c.image, c.image, "\"edge_length\": " + std::to_string(c.edgeLength) + ", ");
    const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
    REQUIRE(built.attempts == 1);
    const double estimate = estimateVertices(tracedArea(built.outlines[0]), tracedPerimeter(built.outlines[0]), c.edgeLength);
    INFO(c.image.width << " px at " << c.edgeLength << " px: estimate " << estimate << ", built " << built.multimesh->vertexCount());
    CHECK(estimate == Approx(built.multimesh->vertexCount()).epsilon(0.15));
  }
}

TEST_CASE("mesh size: past max_vertices the build is refused before meshing, naming the scene, the estimate and what to do") {
  // 1024 px disc at 0.5 px: about 7.5 million vertices, minutes and gigabytes to build.
  const RgbaImage big = test::drawShape(1024, 1024, test::disc(512, 512, 440), 40, 90, 200);
  const Scene scene = writeScene("mesh-size-guard", big, big, "\"edge_length\": 0.5, ");
  const auto started = std::chrono::steady_clock::now();
  try {
    buildMultimesh(scene, MultimeshBuildOptions{});
    FAIL("the build was not refused");
  } catch (const InputError& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.rfind("scene.json: edge_length 0.5 px would give a multimesh of about ", 0) == 0);
    CHECK(message.find("more than max_vertices 200,000") != std::string::npos);
    CHECK(message.find("set \"edge_length\" to ") != std::string::npos);
    CHECK(message.find("raise \"max_vertices\"") != std::string::npos);
  }
  // Tracing only: the refused build takes about a second; meshing it would take minutes.
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() < 30);
}

TEST_CASE("mesh size: the suggested edge length fits the limit, and the default never trips the guard") {
  const std::vector<Outline> disc = traced(test::drawShape(512, 512, test::disc(256, 256, 230)));
  Scene scene = parseScene("{\"version\": 1, \"edge_length\": 0.5, \"max_vertices\": 5000, \"keys\": [{\"name\": \"a\", \"drawing\": \"a.png\"}]}",
                           "guard.json");
  CHECK(scene.maxVertices == 5000);
  std::string message;
  try {
    meshEdgeLength(scene, {disc});
  } catch (const InputError& e) {
    message = e.what();
  }
  const size_t at = message.find("set \"edge_length\" to ");
  REQUIRE(at != std::string::npos);
  const double suggested = std::stod(message.substr(at + 21));
  CHECK(estimateVertices(tracedArea(disc), tracedPerimeter(disc), suggested) <= 5000);
  CHECK(estimateVertices(tracedArea(disc), tracedPerimeter(disc), suggested * 0.9) > 5000);  // and not much coarser
  CHECK(withinMeshLimit(scene, disc, suggested));

  scene.edgeLength = 0;  // the default: 8 px by the rule, raised to what fits 5000 vertices
  const double e = meshEdgeLength(scene, {disc});
  CHECK(e > 8);
  CHECK(estimateVertices(tracedArea(disc), tracedPerimeter(disc), e) == Approx(5000).epsilon(1e-6));
}

TEST_CASE("mesh size: max_vertices and sampling are scene fields with bounds and named errors") {
  const auto parse = [](const std::string& fields) {
    return parseScene("{\"version\": 1, " + fields + "\"keys\": [{\"name\": \"a\", \"drawing\": \"a.png\"}]}", "fields.json");
  };
  CHECK(parse("").maxVertices == 200000);
  CHECK(parse("").sampling == ArtworkSampling::kAuto);
  CHECK(parse("").edgeLength == 0);
  CHECK(parse("\"max_vertices\": 1000000, ").maxVertices == 1000000);
  CHECK(parse("\"sampling\": \"nearest\", ").sampling == ArtworkSampling::kNearest);
  CHECK(parse("\"sampling\": \"linear\", ").sampling == ArtworkSampling::kLinear);
  CHECK(parse("\"sampling\": \"auto\", ").sampling == ArtworkSampling::kAuto);
  CHECK_THROWS_WITH(parse("\"sampling\": \"bilinear\", "),
                    Catch::Contains("fields.json: sampling: \"bilinear\" is not \"auto\"") && Catch::Contains("did you mean \"linear\""));
  CHECK_THROWS_WITH(parse("\"max_vertices\": 10, "), Catch::Contains("max_vertices"));
  CHECK_THROWS_WITH(parse("\"max_vertices\": 1000.5, "), Catch::Contains("max_vertices: must be a whole number"));
  CHECK(parse("\"edge_length\": 0, ").edgeLength == 0);  // 0 follows the drawings, as absent
  CHECK_THROWS_WITH(parse("\"edge_length\": 0.25, "), Catch::Contains("edge_length: 0.25 is out of range 0 (follow the drawings) or [0.5"));
}

TEST_CASE("sampling: auto is nearest for hard-edged small-palette drawings only") {
  const std::vector<RgbaImage> pixelArt = {test::slimePixelArt(false), test::slimePixelArt(true)};
  CHECK(isPixelArt(pixelArt));
  CHECK_FALSE(isPixelArt({test::birdSprite(64)}));                   // antialiased edges
  CHECK_FALSE(isPixelArt({pixelArt[0], test::birdSprite(64)}));      // every key must be pixel art
  RgbaImage gradient = test::slimePixelArt(false);                   // hard edges, 300 colours
  gradient.width = gradient.height = 20;
  gradient.pixels.assign(20 * 20 * 4, 255);
  for (int i = 0; i < 400; ++i) gradient.pixels[4 * i] = static_cast<uint8_t>(i), gradient.pixels[4 * i + 1] = static_cast<uint8_t>(i / 256);
  CHECK_FALSE(isPixelArt({gradient}));
  CHECK_FALSE(isPixelArt({}));

  Scene scene = parseScene("{\"version\": 1, \"keys\": [{\"name\": \"a\", \"drawing\": \"a.png\"}]}", "s.json");
  CHECK(nearestSampling(scene, pixelArt));
  CHECK_FALSE(nearestSampling(scene, {test::birdSprite(64)}));
  scene.sampling = ArtworkSampling::kLinear;
  CHECK_FALSE(nearestSampling(scene, pixelArt));
  scene.sampling = ArtworkSampling::kNearest;
  CHECK(nearestSampling(scene, {test::birdSprite(64)}));
}
