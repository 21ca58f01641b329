#include "error.h"
#include "scene.h"

#include <catch2/catch.hpp>

using namespace ib;
using nlohmann::json;

namespace {

// The paper's Figure 2 split: the square carries a notch from its bottom edge; the arch places
// the notch's features at its inner feet and apex.
json squareArch() {
  return json::parse(R"({
    "version": 1,
    "reference": "square",
    "edge_length": 6,
    "tracing": {"tolerance": 0.1, "min_area": 9},
    "solver": {"lambda": 4000, "tau": 0.002, "alpha": 0.3, "non_overlap": true},
    "keys": [
      {"name": "square", "drawing": "square.png",
       "features": {"top": [64, 24]},
       "cuts": [{"name": "split", "kind": "notch", "points": [[64, 104], [64, 60]]}]},
      {"name": "arch", "drawing": "drawings/arch.png",
       "features": {"top": [64, 20], "split.left": [52, 104], "split.right": [76, 104], "split.tip": [64, 58]}}
    ]
  })");
}

std::string messageOf(const json& scene) {
  try {
    parseScene(scene.dump(), "scenes/square-arch.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("scene: a valid scene reads with its keys, features, cuts, parameters and resolved paths") {
  const Scene s = parseScene(squareArch().dump(), "scenes/square-arch.json");
  REQUIRE(s.keys.size() == 2);
  CHECK(s.reference == 0);
  CHECK(s.edgeLength == 6);
  CHECK(s.keys[0].drawing == "scenes/square.png");
  CHECK(s.keys[1].drawing == "scenes/drawings/arch.png");
  REQUIRE(s.keys[0].cuts.size() == 1);
  CHECK(s.keys[0].cuts[0].kind == CutKind::kNotch);
  CHECK(s.keys[0].cuts[0].points.size() == 2);
  CHECK(s.keys[1].features.at("split.tip") == Eigen::Vector2d(64, 58));
  CHECK(s.tracing.minArea == 9);
  CHECK(s.solver.tau == 0.002);
  CHECK(s.solver.alpha == 0.3);
  CHECK(s.solver.kappa == 1);  // default
  CHECK(s.solver.nonOverlap);
}

TEST_CASE("scene: a key that does not place a cut's feature is named with the cut and the feature") {
  json j = squareArch();
  j["keys"][1]["features"].erase("split.tip");
  CHECK(messageOf(j) == "square-arch.json: cut \"split\": key \"arch\" does not place feature \"split.tip\"");
}

TEST_CASE("scene: every malformed or inconsistent field is an input error naming file, key and field") {
  const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
      {[](json& j) { j["colour"] = 1; }, "square-arch.json: unknown field \"colour\""},
      {[](json& j) { j["keys"][1]["feature"] = json::object(); }, "key: unknown field \"feature\""},
      {[](json& j) { j["version"] = 2; }, "version: must be 1"},
      {[](json& j) { j["edge_length"] = -1; }, "edge_length: -1"},
      {[](json& j) { j["reference"] = "circle"; }, "reference: must name one of the keys"},
      {[](json& j) { j["solver"]["alpha"] = 1.5; }, "solver: alpha: 1.5 is out of range"},
      {[](json& j) { j["solver"]["tau"] = 0; }, "solver: tau: 0"},
      {[](json& j) { j["tracing"]["alpha_threshold"] = 0; }, "tracing: alpha_threshold"},
      {[](json& j) { j["tracing"]["background"] = {255, 255}; }, "tracing: background: must be [r, g, b]"},
      {[](json& j) { j["keys"][1]["name"] = "square"; }, "key \"square\": is named twice"},
      {[](json& j) { j["keys"][1].erase("drawing"); }, "key \"arch\": missing field \"drawing\""},
      {[](json& j) { j["keys"][1]["features"]["top"] = {1}; }, "key \"arch\": feature \"top\": must be a point"},
      {[](json& j) { j["keys"][1]["features"].erase("top"); }, "key \"arch\": does not place feature \"top\""},
      {[](json& j) { j["keys"][0]["cuts"][0]["kind"] = "tear"; }, "cut \"split\": kind: \"tear\" is not a cut kind"},
      {[](json& j) { j["keys"][0]["cuts"][0]["points"] = {{1, 2}}; }, "cut \"split\": needs \"points\""},
      {[](json& j) { j["keys"][0]["cuts"][0]["name"] = "a.b"; }, "may not contain '.'"},
      {[](json& j) { j["keys"][0]["features"]["split.tip"] = {64, 60}; }, "key \"square\" draws the cut"},
      {[](json& j) { j["keys"][1]["features"]["split.mouth"] = {1, 1}; }, "feature \"split.mouth\" is not one"},
      {[](json& j) { j["keys"][1]["features"]["gap.tip"] = {1, 1}; }, "feature \"gap.tip\" names no cut"},
      {[](json& j) { j["keys"][1]["cuts"] = j["keys"][0]["cuts"]; }, "cut \"split\": is closed in every key"},
      {[](json& j) { j["keys"] = json::array(); }, "keys: needs at least one key"},
  };
  for (const auto& [edit, expected] : cases) {
    json j = squareArch();
    edit(j);
    const std::string message = messageOf(j);
    INFO("expected \"" << expected << "\", got \"" << message << "\"");
    CHECK(message.rfind("square-arch.json: ", 0) == 0);
    CHECK(message.find(expected) != std::string::npos);
  }
}

TEST_CASE("scene: malformed JSON and a missing scene file are input errors naming the file") {
  CHECK_THROWS_WITH(parseScene("{\"version\": 1,", "bad.json"), Catch::StartsWith("bad.json: malformed JSON"));
  CHECK_THROWS_AS(loadScene("no-such-scene.json"), InputError);
  CHECK_THROWS_WITH(loadScene("no-such-scene.json"), Catch::Contains("no-such-scene.json"));
}

TEST_CASE("scene: cut features are named after the cut and the kind of its ends") {
  CHECK(cutFeatureNames("s", CutKind::kNotch) == std::vector<std::string>{"s.left", "s.right", "s.tip"});
  CHECK(cutFeatureNames("s", CutKind::kSplit).size() == 4);
  CHECK(cutFeatureNames("s", CutKind::kSlit) == std::vector<std::string>{"s.start", "s.end"});
}
