// Outline corners (meshing/outline_corners.h) and what the shared boundary does with them
// ("corners" in the scene): detection on loops with known corners, the pairing of corners across
// keys, a boundary vertex at every paired corner in every key, and the drawn wing flaps and leg
// swings (tests/drawn), on which Comesh meets the extreme-deformation targets.
#include "core/error.h"
#include "meshing/multimesh_builder.h"
#include "meshing/outline_corners.h"
#include "multimesh/mesh_quality.h"
#include "pipeline/scene_multimesh.h"
#include "scene/scene.h"
#include "testkit/drawings.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace ib;

namespace {

// A closed polygon through `corners`, with a point every `step` px along each side.
Polyline densePolygon(const std::vector<Eigen::Vector2d>& corners, double step = 0.5) {
  Polyline out;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2d a = corners[i], b = corners[(i + 1) % corners.size()];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
    for (int j = 0; j < n; ++j) out.push_back(a + (b - a) * (static_cast<double>(j) / n));
  }
  return out;
}

// Distance from p to the nearest detected corner of `loop`, and that corner's turning.
std::pair<double, double> nearestCorner(const ArcLengthLoop& loop, const std::vector<OutlineCorner>& corners,
                                        const Eigen::Vector2d& p) {
  double best = 1e9, turn = 0;
  for (const OutlineCorner& c : corners)
    if ((loop.at(c.s) - p).norm() < best) best = (loop.at(c.s) - p).norm(), turn = c.turn;
  return {best, turn};
}

// Two keys of an L-shaped boot on a 160 px canvas whose concave corner (the instep) moves 30 px
// along the sole between the keys; features at the toe and the heel's top.
std::string writeBootScene(const std::string& name, const std::string& corners) {
  static const std::string scratch = test::scratchDirectory("corners");
  const std::filesystem::path folder = std::filesystem::path(scratch) / name;
  std::filesystem::create_directories(folder);
  writePng((folder / "a.png").string(), test::drawShape(160, 160, test::unite(test::box(20, 20, 60, 140), test::box(20, 100, 140, 140))));
  writePng((folder / "b.png").string(), test::drawShape(160, 160, test::unite(test::box(20, 20, 90, 140), test::box(20, 110, 140, 140))));
  const std::string file = (folder / "scene.json").string();
  std::ofstream(file) << "{\"version\": 1, \"edge_length\": 6" << (corners.empty() ? "" : ", \"corners\": \"" + corners + "\"")
                      << ", \"keys\": [{\"name\": \"a\", \"drawing\": \"a.png\", \"features\": {\"heel\": [20, 20], \"toe\": [140, 140]}},"
                         " {\"name\": \"b\", \"drawing\": \"b.png\", \"features\": {\"heel\": [20, 20], \"toe\": [140, 140]}}]}";
  return file;
}

// Distance from p to the nearest outline vertex of key k.
double nearestBoundaryVertex(const Multimesh& mesh, int k, const Eigen::Vector2d& p) {
  const Eigen::MatrixX2d x = mesh.keyPositions(k);
  double best = 1e9;
  for (int v : mesh.boundaryVertices(k)) best = std::min(best, (x.row(v).transpose() - p).norm());
  return best;
}

// How far from `q` in key `l` the boundary vertex nearest `p` in key `k` lies: near 0 when the
// mesh pairs a corner at p in key k with one at q in key l.
double pairedDistance(const Multimesh& mesh, int k, const Eigen::Vector2d& p, int l, const Eigen::Vector2d& q) {
  const Eigen::MatrixX2d x = mesh.keyPositions(k), y = mesh.keyPositions(l);
  int nearest = -1;
  double best = 1e9;
  for (int v : mesh.boundaryVertices(k))
    if ((x.row(v).transpose() - p).norm() < best) best = (x.row(v).transpose() - p).norm(), nearest = v;
  return (y.row(nearest).transpose() - q).norm();
}

}  // namespace

TEST_CASE("corners: a square's four corners are found within 0.5 px, convex, and a circle has none") {
  const std::vector<Eigen::Vector2d> square = {{10, 10}, {90, 10}, {90, 90}, {10, 90}};
  Polyline ccw = densePolygon(square);
  if (loopArea(ccw) < 0) std::reverse(ccw.begin(), ccw.end());
  const ArcLengthLoop loop(ccw);
  const std::vector<OutlineCorner> corners = outlineCorners(loop, OutlineCornerOptions{});
  REQUIRE(corners.size() == 4);
  for (const Eigen::Vector2d& p : square) {
    const auto [distance, turn] = nearestCorner(loop, corners, p);
    CHECK(distance <= 0.5);
    CHECK(turn == Approx(M_PI / 2).margin(0.15));
  }
  Polyline circle;
  for (int i = 0; i < 600; ++i) circle.push_back({80 + 40 * std::cos(2 * M_PI * i / 600), 80 + 40 * std::sin(2 * M_PI * i / 600)});
  if (loopArea(circle) < 0) std::reverse(circle.begin(), circle.end());
  CHECK(outlineCorners(ArcLengthLoop(circle), OutlineCornerOptions{}).empty());
}

TEST_CASE("corners: an L shape's inner corner turns the other way (concave) from its five convex ones") {
  Polyline l = densePolygon({{0, 0}, {60, 0}, {60, 20}, {20, 20}, {20, 80}, {0, 80}});
  if (loopArea(l) < 0) std::reverse(l.begin(), l.end());
  const ArcLengthLoop loop(l);
  const std::vector<OutlineCorner> corners = outlineCorners(loop, OutlineCornerOptions{});
  REQUIRE(corners.size() == 6);
  int concave = 0;
  for (const OutlineCorner& c : corners)
    if (c.turn < 0) {
      ++concave;
      CHECK((loop.at(c.s) - Eigen::Vector2d(20, 20)).norm() <= 0.5);
    }
  CHECK(concave == 1);
}

TEST_CASE("corners: pairing keeps the order and sign of corners, one missing from a key pairs nothing there") {
  // Reference (key 0): a concave corner at 0.3 and a convex one at 0.7. Key 1 has both, shifted;
  // key 2 only the concave one.
  const std::vector<std::vector<ArcCorner>> corners = {
      {{0.3, -1.2}, {0.7, 1.0}}, {{0.4, -1.0}, {0.6, 1.1}}, {{0.35, -1.3}}};
  CornerMatchOptions paired;
  paired.unpaired = false;
  const std::vector<CornerKnot> knots = cornerKnots(corners, {100, 120, 90}, 0, paired);
  REQUIRE(knots.size() == 1);
  CHECK(knots[0].fractions == std::vector<double>{0.3, 0.4, 0.35});
  CHECK(knots[0].corner == std::vector<char>{1, 1, 1});
  // Opposite signs never pair: a convex corner where the reference has a concave one.
  const std::vector<CornerKnot> none = cornerKnots({{{0.5, -1.0}}, {{0.5, 1.0}}}, {100, 100}, 0, paired);
  CHECK(none.empty());
}

TEST_CASE("corners: two corners at the same place along the arc but far apart in the plane (after the squash is undone) "
          "do not pair; near each other they do") {
  CornerMatchOptions paired;
  paired.unpaired = false;
  // A 200 px arc; the key's corner 2% further along, turning alike: by fraction alone a pair.
  const ArcCorner beak{0.50, 1.0, Eigen::Vector2d(75, 54)};
  const ArcCorner foot{0.52, 1.0, Eigen::Vector2d(75, 118)};  // 64 px away: 0.32 of the arc, more than two unpaired
  CHECK(cornerKnots({{beak}, {foot}}, {200, 200}, 0, paired).empty());
  const ArcCorner near{0.52, 1.0, Eigen::Vector2d(76, 55)};
  CHECK(cornerKnots({{beak}, {near}}, {200, 200}, 0, paired).size() == 1);
  // Without places (NaN) the fraction and the turning decide, as before.
  CHECK(cornerKnots({{{0.50, 1.0}}, {{0.52, 1.0}}}, {200, 200}, 0, paired).size() == 1);
}

TEST_CASE("corners: with \"vertices\", an unpaired corner is a knot held in its own key only, carried to the others") {
  const std::vector<std::vector<ArcCorner>> corners = {{{0.5, -1.0}}, {{0.5, -1.0}, {0.8, 1.0}}};
  CornerMatchOptions options;
  options.unpaired = true;
  options.mergeDistance = 4;
  const std::vector<CornerKnot> knots = cornerKnots(corners, {100, 100}, 0, options);
  REQUIRE(knots.size() == 2);
  CHECK(knots[1].corner == std::vector<char>{0, 1});
  // Carried linearly between the paired knot (0.5 in both) and the arc's end.
  CHECK(knots[1].fractions[0] == Approx(0.8));
  // Two keys' unpaired corners within the merge distance of each other are one knot.
  const std::vector<CornerKnot> merged = cornerKnots({{}, {{0.5, -1.0}}, {{0.52, -1.0}}}, {100, 100, 100}, 0, options);
  REQUIRE(merged.size() == 1);
  CHECK(merged[0].corner == std::vector<char>{0, 1, 1});
  CHECK(merged[0].fractions[2] == Approx(0.52));
}

TEST_CASE("corners: paired corners are one boundary vertex at the corner in every key, with \"off\" the moving one is not") {
  const Eigen::Vector2d instepA(60, 100), instepB(90, 110);  // the concave corner in keys a and b
  const BuiltScene paired = buildMultimesh(loadScene(writeBootScene("paired", "")), MultimeshBuildOptions{});
  CHECK(nearestBoundaryVertex(*paired.multimesh, 0, instepA) <= 0.75);
  CHECK(nearestBoundaryVertex(*paired.multimesh, 1, instepB) <= 0.75);
  CHECK(pairedDistance(*paired.multimesh, 0, instepA, 1, instepB) <= 0.75);
  // The convex corners that stay put too.
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(60, 20), Eigen::Vector2d(20, 140)})
    CHECK(nearestBoundaryVertex(*paired.multimesh, 0, p) <= 0.75);
  // With "off" the boundary still follows each key's outline (knots where the arcs curve put a
  // vertex near the instep in each key), but the instep of one key is not the other's: the
  // vertex at key a's instep lies elsewhere in key b.
  const BuiltScene off = buildMultimesh(loadScene(writeBootScene("off", "off")), MultimeshBuildOptions{});
  CHECK(pairedDistance(*off.multimesh, 0, instepA, 1, instepB) > 1.0);
}

TEST_CASE("corners: an unknown \"corners\" value names the field and the values it may take") {
  const std::string file = writeBootScene("bad", "sharp");
  CHECK_THROWS_WITH(loadScene(file), Catch::Contains("corners") && Catch::Contains("\"sharp\" is not \"paired\"") &&
                                         Catch::Contains("\"off\""));
}

namespace {

// The extreme-deformation targets (issue "Real drawings") on the scene built from its drawings
// with Comesh: every key's smallest angle >= 10 deg with at most 2% of triangles under 20 deg, and
// every map's MIPS maximum under 20.
void checkExtremeDeformationTargets(const Scene& scene) {
  SceneMultimeshOptions options;
  options.useCache = false;
  const SceneMultimesh built = sceneMultimesh(scene, options);
  const MultimeshQuality quality = measureQuality(*built.multimesh);
  for (size_t k = 0; k < quality.keys.size(); ++k) {
    INFO("key " << scene.keys[k].name);
    CHECK(quality.keys[k].smallestAngle >= 10);
    CHECK(quality.keys[k].shareUnder20 <= 0.02);
  }
  for (const MapQuality& map : quality.maps) {
    INFO("map " << scene.keys[map.from].name << " -> " << scene.keys[map.to].name);
    CHECK(map.mipsMax < 20);
  }
}

}  // namespace

TEST_CASE("extreme deformation: the drawn wing flaps, leg swings and bending tails after Comesh have every key's smallest angle >= 10 deg, <= 2% under 20 deg, MIPS max < 20") {
  // bat512 pairs its armpits by itself; at 96 px they are too soft to be corners and the scene
  // places them as features (bat96.json, with the wing tips only, does not meet the targets).
  for (const char* name : {"bat/bat512.json", "bat/bat96-armpits.json", "leg/leg64.json", "leg/leg512.json",
                           "tail/tail96.json", "tail/tail512.json"}) {
    INFO("tests/drawn/" << name);
    checkExtremeDeformationTargets(loadScene(std::string(INBETWEEN_ASSETS "/../tests/drawn/") + name));
  }
}

TEST_CASE("extreme deformation: adding consistent features (the top and bottom of the bat's body) keeps the build working and within the targets") {
  for (const char* name : {"bat512", "bat96-armpits"}) {
    INFO("tests/drawn/bat/" << name << ".json with features crown and tail");
    Scene scene = loadScene(std::string(INBETWEEN_ASSETS "/../tests/drawn/bat/") + name + ".json");
    const double s = std::string(name) == "bat512" ? 1.0 : 96.0 / 512;  // the body does not move between keys
    for (KeySpec& key : scene.keys) {
      key.features["crown"] = Eigen::Vector2d(256, 210) * s;
      key.features["tail"] = Eigen::Vector2d(256, 350) * s;
    }
    checkExtremeDeformationTargets(scene);
  }
}
