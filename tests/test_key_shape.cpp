#include "core/error.h"
#include "meshing/key_shape.h"
#include "meshing/shared_boundary.h"
#include "meshing/untangle.h"

#include <catch2/catch.hpp>

using namespace ib;

namespace {

// The square [0, 100]^2 as traced: interior on the left in a y-up frame (positive loopArea).
Outline squareOutline(double x0 = 0, double size = 100) {
  Outline o;
  o.outer = {{x0, 0}, {x0 + size, 0}, {x0 + size, size}, {x0, size}};
  REQUIRE(loopArea(o.outer) > 0);
  return o;
}

Scene sceneWith(const std::vector<KeySpec>& keys) {
  Scene s;
  s.file = "dir/test.json";
  s.keys = keys;
  return s;
}

KeySpec keyWithCut(const std::string& name, CutKind kind, Polyline points) {
  KeySpec k;
  k.name = name;
  CutSpec cut;
  cut.name = "c";
  cut.kind = kind;
  cut.points = std::move(points);
  k.cuts.push_back(cut);
  return k;
}

std::vector<std::string> featureOrder(const ShapeLoop& loop) {
  std::vector<std::string> out;
  for (const auto& f : loop.features)
    if (!f.empty()) out.push_back(f);
  return out;
}

}  // namespace

TEST_CASE("key shape: a notch walks in along its right side and out along its left, as seen walking in") {
  // Up the screen from the bottom edge (y = 100) to (50, 40): screen-left is smaller x.
  const Scene scene = sceneWith({keyWithCut("k", CutKind::kNotch, {{50, 100}, {50, 70}, {50, 40}})});
  const KeyShape shape = buildKeyShape(scene, 0, {squareOutline()}, KeyShapeOptions{});
  REQUIRE(shape.loops.size() == 1);
  const ShapeLoop& loop = shape.loops[0];
  const auto [l, right] = findFeature(shape, "c.right");
  const auto [l2, tip] = findFeature(shape, "c.tip");
  const auto [l3, left] = findFeature(shape, "c.left");
  CHECK(tip == right + 2);  // right mouth, the middle cut point, the tip
  CHECK(left == tip + 2);
  CHECK(loop.points[right] == loop.points[left]);             // both mouths at the snapped start
  CHECK(loop.points[right + 1] == loop.points[left - 1]);     // sides are exact copies
  CHECK(loop.points[tip] == Eigen::Vector2d(50, 40));
  // The point before the right mouth lies on the screen-right (x > 50), the one after the left mouth on x < 50.
  const size_t n = loop.points.size();
  CHECK(loop.points[(right + n - 1) % n].x() > 50);
  CHECK(loop.points[(left + 1) % n].x() < 50);
  CHECK(std::abs(loopArea(loop.points) - 100 * 100) < 1e-9);  // a zero-width notch removes no area
}

TEST_CASE("key shape: a split across the shape separates one loop into two, a slit adds a loop") {
  const Scene split = sceneWith({keyWithCut("k", CutKind::kSplit, {{50, 0}, {50, 100}})});
  const KeyShape halves = buildKeyShape(split, 0, {squareOutline()}, KeyShapeOptions{});
  REQUIRE(halves.loops.size() == 2);
  CHECK(featureOrder(halves.loops[0]) == std::vector<std::string>{"c.start.right", "c.end.right"});
  CHECK(featureOrder(halves.loops[1]) == std::vector<std::string>{"c.end.left", "c.start.left"});
  CHECK(std::abs(loopArea(halves.loops[0].points) + loopArea(halves.loops[1].points) - 1e4) < 1e-9);
  // Walking down the screen from (50, 0), screen-right is smaller x.
  CHECK(loopArea(halves.loops[0].points) > 0);
  for (const auto& p : halves.loops[0].points) CHECK(p.x() <= 50);

  const Scene slit = sceneWith({keyWithCut("k", CutKind::kSlit, {{30, 50}, {70, 50}})});
  const KeyShape holed = buildKeyShape(slit, 0, {squareOutline()}, KeyShapeOptions{});
  REQUIRE(holed.loops.size() == 2);
  CHECK(featureOrder(holed.loops[1]) == std::vector<std::string>{"c.start", "c.end"});
}

TEST_CASE("key shape: a split from the outline to a hole joins the two loops into one") {
  Outline holed = squareOutline();
  holed.holes.push_back({{40, 40}, {40, 60}, {60, 60}, {60, 40}});
  REQUIRE(loopArea(holed.holes[0]) < 0);
  const Scene join = sceneWith({keyWithCut("k", CutKind::kSplit, {{50, 100}, {50, 60}})});
  const KeyShape joined = buildKeyShape(join, 0, {holed}, KeyShapeOptions{});
  REQUIRE(joined.loops.size() == 1);
  CHECK(featureOrder(joined.loops[0]).size() == 4);
  CHECK(std::abs(loopArea(joined.loops[0].points) - (1e4 - 400)) < 1e-9);
}

TEST_CASE("key shape: features and cut ends off the outline, and cuts leaving the shape, are named errors") {
  KeySpec far;
  far.name = "k";
  far.features["nose"] = {50, 30};
  CHECK_THROWS_WITH(buildKeyShape(sceneWith({far}), 0, {squareOutline()}, KeyShapeOptions{}),
                    Catch::Contains("test.json: key \"k\": feature \"nose\"") && Catch::Contains("30 px from the outline"));
  const Scene inside = sceneWith({keyWithCut("k", CutKind::kNotch, {{50, 50}, {50, 40}})});
  CHECK_THROWS_WITH(buildKeyShape(inside, 0, {squareOutline()}, KeyShapeOptions{}),
                    Catch::Contains("cut \"c\": its first point") && Catch::Contains("must lie on the outline"));
  const Scene leaving = sceneWith({keyWithCut("k", CutKind::kSlit, {{50, 50}, {150, 50}})});
  CHECK_THROWS_WITH(buildKeyShape(leaving, 0, {squareOutline()}, KeyShapeOptions{}),
                    Catch::Contains("leaves the shape") && Catch::Contains("(100.0, 50.0)"));
}

namespace {

ShapeLoop plain(Polyline points) { return {points, std::vector<std::string>(points.size())}; }
ShapeLoop hole(double x0, double y0, double size) {  // clockwise in a y-up frame: negative loopArea
  return plain({{x0, y0}, {x0, y0 + size}, {x0 + size, y0 + size}, {x0 + size, y0}});
}
Scene twoKeys() {
  KeySpec a, b;
  a.name = "a";
  b.name = "b";
  return sceneWith({a, b});
}
std::string mismatchOf(const std::vector<ShapeLoop>& a, const std::vector<ShapeLoop>& b) {
  try {
    matchBoundaries(twoKeys(), {KeyShape{"a", a}, KeyShape{"b", b}}, SharedBoundaryOptions{});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("shared boundary: a featureless loop traced from another start point is started where it fits") {
  // The same square in both keys, the second traced from a different corner.
  Scene scene = twoKeys();
  KeyShape a{"a", {{squareOutline().outer, std::vector<std::string>(4)}}};
  Polyline shifted = {{100, 100}, {0, 100}, {0, 0}, {100, 0}};
  KeyShape b{"b", {{shifted, std::vector<std::string>(4)}}};
  const SharedBoundary boundary = matchBoundaries(scene, {a, b}, SharedBoundaryOptions{});
  for (double u : {0.0, 0.1, 0.37, 0.8}) CHECK((boundary.at(0, 0, u) - boundary.at(1, 0, u)).norm() < 1.0);
}

TEST_CASE("shared boundary: a feature on another loop is reported with the key and both loops' features") {
  Scene scene = twoKeys();
  ShapeLoop one{squareOutline().outer, {"p", "q", "", ""}};
  ShapeLoop first{squareOutline().outer, {"p", "", "", ""}}, second{squareOutline(150).outer, {"q", "", "", ""}};
  CHECK_THROWS_WITH(matchBoundaries(scene, {KeyShape{"a", {one}}, KeyShape{"b", {first, second}}}, SharedBoundaryOptions{}),
                    Catch::StartsWith("test.json: outlines do not match: in key \"a\" \"p\" and \"q\" are on one piece "
                                      "around (50, 50), 10000 px\u00b2") &&
                        Catch::Contains("but in key \"b\" \"q\" is on a piece around (200, 50), 10000 px\u00b2 (with \"q\")") &&
                        Catch::Contains("a \"split\" cut in key \"a\" where its piece comes apart") &&
                        Catch::Contains("if \"q\" is on the wrong outline, move it") && !Catch::Contains("loop"));
}


TEST_CASE("shared boundary: an extra hole names its key, where it is, its area and the cuts that make the topology match") {
  const ShapeLoop square = plain(squareOutline().outer);
  const std::string message = mismatchOf({square}, {square, hole(40, 40, 20)});
  INFO(message);
  CHECK(message.rfind("test.json: outlines do not match: key \"b\" has a hole that key \"a\" does not", 0) == 0);
  CHECK(message.find("hole around (50, 50), 400 px\u00b2") != std::string::npos);
  CHECK(message.find("draw a \"slit\" cut in key \"a\" where it opens") != std::string::npos);
  CHECK(message.find("draw a \"split\" cut in key \"b\" from the hole to the outline") != std::string::npos);
  CHECK(message.find("fill it in key \"b\"'s drawing") != std::string::npos);
  CHECK(message.find("When the keys' topology differs") != std::string::npos);
  CHECK(message.find("loop") == std::string::npos);
  CHECK(message.find("place features") == std::string::npos);
  // The other way round: the reference key has the hole.
  CHECK(mismatchOf({square, hole(40, 40, 20)}, {square}).find("key \"a\" has a hole that key \"b\" does not") != std::string::npos);
}

TEST_CASE("shared boundary: an extra piece names its key, where it is, its area and the split that makes the topology match") {
  const ShapeLoop square = plain(squareOutline().outer), speck = plain(squareOutline(150, 20).outer);
  const std::string message = mismatchOf({square}, {square, speck});
  INFO(message);
  CHECK(message.find("key \"b\" has a piece that key \"a\" does not (of the pieces without features, \"b\" has 2 and "
                     "\"a\" 1): piece around (160, 10), 400 px\u00b2") != std::string::npos);
  CHECK(message.find("draw a \"split\" cut in key \"a\" where the pieces separate") != std::string::npos);
  CHECK(message.find("erase it from key \"b\"'s drawing") != std::string::npos);
  // A hole in one key and a piece in the other: both are named.
  const std::string both = mismatchOf({square, hole(40, 40, 20)}, {square, speck});
  CHECK(both.find("key \"b\" has a piece that key \"a\" does not") != std::string::npos);
  CHECK(both.find("; and key \"a\" has a hole that key \"b\" does not") != std::string::npos);
}

TEST_CASE("shared boundary: holes that fit as well either way round ask for features, holes that moved a little match") {
  const ShapeLoop square = plain(squareOutline().outer);
  const std::string turned = mismatchOf({square, hole(20, 40, 20), hole(60, 40, 20)}, {square, hole(40, 20, 20), hole(40, 60, 20)});
  INFO(turned);
  CHECK(turned.find("about as well either way round: place a feature on each of them, in every key") != std::string::npos);
  CHECK(mismatchOf({square, hole(20, 40, 20), hole(60, 40, 20)}, {square, hole(24, 42, 20), hole(63, 38, 20)}) == "no error");
}

TEST_CASE("untangle: a grid with folded interior vertices and a fixed boundary ends with every triangle positive") {
  const int n = 8;  // (n+1)^2 vertices on [0, n]^2
  Eigen::MatrixX2d rest((n + 1) * (n + 1), 2);
  std::vector<Triangle> triangles;
  std::vector<char> locked(rest.rows());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      rest.row(j * (n + 1) + i) << i, j;
      locked[j * (n + 1) + i] = i == 0 || j == 0 || i == n || j == n;
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int v = j * (n + 1) + i;
      triangles.push_back({v, v + 1, v + n + 2});
      triangles.push_back({v, v + n + 2, v + n + 1});
    }
  Eigen::MatrixX2d x = rest;
  for (int v = 0; v < x.rows(); ++v)
    if (!locked[v]) x.row(v) = Eigen::RowVector2d(n - rest(v, 1), rest(v, 0)) * 0.3 + Eigen::RowVector2d(7.5, 0.5);
  REQUIRE(smallestTriangleArea(triangles, x).first < 0);
  const UntangleResult r = untangle(triangles, rest, x, locked, UntangleOptions{});
  CHECK(r.injective);
  CHECK(smallestTriangleArea(triangles, x).first > 0);
  for (int v = 0; v < x.rows(); ++v)
    if (locked[v]) CHECK(x.row(v) == rest.row(v));
}
