#include "core/error.h"
#include "core/plane_geometry.h"
#include "meshing/multimesh_builder.h"
#include "testkit/drawings.h"
#include "testkit/example_scenes.h"
#include "testkit/shape_checks.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <map>

using namespace ib;

namespace {

// Every good example scene with every key as the reference ("NAME@KEY"), built once per test
// run. The open key as reference exercises points the mesher adds on one side of a cut only.
const std::map<std::string, std::pair<Scene, BuiltScene>>& builtScenes() {
  static const auto built = [] {
    const std::string folder = test::scratchDirectory("builder");
    std::map<std::string, std::pair<Scene, BuiltScene>> out;
    for (const auto& example : test::goodScenes()) {
      test::writeScene(example, folder);
      Scene scene = loadScene((std::filesystem::path(folder) / example.name / "scene.json").string());
      for (size_t k = 0; k < scene.keys.size(); ++k) {
        scene.reference = static_cast<int>(k);
        out.emplace(example.name + "@" + scene.keys[k].name,
                    std::make_pair(scene, buildMultimesh(scene, MultimeshBuildOptions{})));
      }
    }
    return out;
  }();
  return built;
}

const BuiltScene& builtScene(const std::string& name) {
  for (const auto& [key, entry] : builtScenes())
    if (key.rfind(name + "@", 0) == 0) return entry.second;
  throw std::logic_error("no example scene " + name);
}

}  // namespace

TEST_CASE("multimesh builder: every example scene builds with positive triangle areas in every key") {
  for (const auto& [name, entry] : builtScenes()) {
    INFO("scene " << name);
    const Multimesh& mesh = *entry.second.multimesh;
    REQUIRE(mesh.keyCount() == static_cast<int>(entry.first.keys.size()));
    CHECK(mesh.triangleCount() > 100);
    for (int k = 0; k < mesh.keyCount(); ++k) {
      const Eigen::MatrixX2d x = mesh.keyPositions(k);
      for (const Triangle& t : mesh.triangles())
        REQUIRE(signedArea(x.row(t[0]), x.row(t[1]), x.row(t[2])) > 1e-9);
    }
    CHECK_NOTHROW(mesh.validate());
  }
}

TEST_CASE("multimesh builder: cohesive pairs are collocated exactly in the keys that close a cut") {
  for (const auto& [name, entry] : builtScenes()) {
    INFO("scene " << name);
    const Multimesh& mesh = *entry.second.multimesh;
    for (int k = 0; k < mesh.keyCount(); ++k) {
      const bool closes = !entry.first.keys[k].cuts.empty();
      const auto& pairs = mesh.cohesivePairs(k);
      CHECK((pairs.empty()) == !closes);
      const Eigen::MatrixX2d x = mesh.keyPositions(k);
      for (const CohesivePair& p : pairs) {
        REQUIRE(x.row(p.a) == x.row(p.c));
        REQUIRE(x.row(p.b) == x.row(p.d));
        REQUIRE(!(p.a == p.c && p.b == p.d));  // two sides, not one edge twice (they may share a tip)
      }
    }
  }
}

TEST_CASE("multimesh builder: boundary vertices lie on their key's outline within 0.5 px") {
  for (const auto& [name, entry] : builtScenes()) {
    INFO("scene " << name);
    const Multimesh& mesh = *entry.second.multimesh;
    const std::vector<int> boundary = test::meshBoundary(mesh);
    for (int k = 0; k < mesh.keyCount(); ++k) {
      INFO("key " << entry.first.keys[k].name);
      const Eigen::MatrixX2d x = mesh.keyPositions(k);
      double worst = 0;
      for (int v : boundary) worst = std::max(worst, test::distanceToShape(entry.second.shapes[k], x.row(v)));
      CHECK(worst <= 0.5);
    }
  }
}

TEST_CASE("multimesh builder: features sit where they were placed, snapped to the outline or a corner of it") {
  for (const auto& [name, entry] : builtScenes()) {
    INFO("scene " << name);
    const Multimesh& mesh = *entry.second.multimesh;
    for (int k = 0; k < mesh.keyCount(); ++k) {
      KeyShape traced;  // the drawing's outlines, before cuts
      for (const Outline& o : entry.second.outlines[k]) {
        traced.loops.push_back({o.outer, {}});
        for (const Polyline& h : o.holes) traced.loops.push_back({h, {}});
      }
      const Eigen::MatrixX2d x = mesh.keyPositions(k);
      for (const auto& [feature, placed] : entry.first.keys[k].features) {
        INFO("key " << entry.first.keys[k].name << ", feature " << feature);
        double nearest = std::numeric_limits<double>::infinity();
        Eigen::Vector2d at = placed;
        for (int v = 0; v < mesh.vertexCount(); ++v)
          if ((x.row(v).transpose() - placed).norm() < nearest) {
            nearest = (x.row(v).transpose() - placed).norm();
            at = x.row(v).transpose();
          }
        // A vertex on the traced outline (at the nearest outline point, or on a corner of the
        // outline within KeyShapeOptions::cornerSnap: a stroke's miter lies a little beyond the
        // placed tip), within 1 px of the placed point: the scenes place features on the drawn edge.
        INFO("vertex at " << at.x() << ", " << at.y() << ", " << nearest << " px from the placed point");
        CHECK(test::distanceToShape(traced, at) <= 1e-6);
        CHECK(nearest <= 1.0);
      }
    }
  }
}

TEST_CASE("multimesh builder: the slit opens a hole and the split makes two components") {
  const Multimesh& ring = *builtScene("disc-ring").multimesh;
  CHECK(ring.boundaryLoops().size() == 2);  // outer outline and the slit's loop
  const BuiltScene& cells = builtScene("cell-split");
  CHECK(cells.shapes[0].loops.size() == 2);
  CHECK(cells.shapes[1].loops.size() == 2);
}

TEST_CASE("multimesh builder: nested featureless loops are matched by position and size") {
  const BuiltScene& rings = builtScene("nested-rings");
  const Multimesh& mesh = *rings.multimesh;
  // If loops were matched wrongly the squashed key would fold; positive areas are checked above.
  // Here: the outer outline of the round key maps to the largest loop of the squashed key.
  const Eigen::MatrixX2d round = mesh.keyPositions(0), squashed = mesh.keyPositions(1);
  int far = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v) far = (round.row(v) - Eigen::RowVector2d(64, 64)).norm() > (round.row(far) - Eigen::RowVector2d(64, 64)).norm() ? v : far;
  CHECK((squashed.row(far) - Eigen::RowVector2d(62, 66)).norm() > 45);
}

TEST_CASE("multimesh builder: every bundled asset scene builds and maps without foldovers") {
  const std::vector<std::string> files = test::bundledSceneFiles(INBETWEEN_ASSETS);
  for (const std::string& file : files) {
    INFO("asset " << file);
    const BuiltScene built = buildMultimesh(loadScene(file), MultimeshBuildOptions{});
    for (const KeyReport& key : built.report) CHECK(key.smallestArea > 0);
  }
  CHECK(files.size() >= 5);
}

TEST_CASE("multimesh builder: a key that stays folded is named with the place and every setting tried, after refining") {
  const std::string folder = test::scratchDirectory("builder-fail");
  for (const auto& example : test::goodScenes())
    if (example.name == "square-arch-stretch") test::writeScene(example, folder);
  const Scene scene = loadScene((std::filesystem::path(folder) / "square-arch-stretch" / "scene.json").string());
  MultimeshBuildOptions options;
  options.untangle.outerIterations = 0;  // Tutte alone folds the arch's cavity walls
  options.refinements = 1;
  int attempts = 0;
  options.progress = [&](const std::string& stage, double) { attempts += stage.rfind("meshing", 0) == 0; };
  CHECK_THROWS_WITH(buildMultimesh(scene, options),
                    Catch::Contains("scene.json: key \"arch\": cannot map the mesh onto this key without folding triangles near (") &&
                        Catch::Contains("tried corners \"vertices\", \"paired\", \"off\"") &&
                        Catch::Contains("edge lengths down to 4"));
  CHECK(attempts == 6);  // two edge lengths for each of the three corner settings
  // Under "artwork" each edge length also tries the artwork (and it without shape knots near the
  // fold, twice) before arc length; the error names both correspondences.
  Scene artwork = scene;
  artwork.correspondence = OutlineCorrespondence::kArtwork;
  attempts = 0;
  CHECK_THROWS_WITH(buildMultimesh(artwork, options),
                    Catch::Contains("tried corners \"vertices\", \"paired\", \"off\", correspondence \"artwork\" and \"outline\""));
  CHECK(attempts == 24);  // 3 corner settings x 2 edge lengths x (3 artwork + 1 arc length)
}
