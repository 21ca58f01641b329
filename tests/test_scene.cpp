#include "core/error.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

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
  CHECK(s.interpolation.cohesive.tau == 0.002);
  CHECK(s.interpolation.cohesive.alpha == 0.3);
  CHECK(s.kappa == 1);  // default
  CHECK(s.interpolation.nonOverlap);
  // Absent animation fields: every key a second apart, no dynamics, nothing painted.
  REQUIRE(s.timeline.marks().size() == 2);
  CHECK(s.timeline.marks()[1].time == 1);
  CHECK(!s.dynamics.enabled());
  CHECK(s.stiffness.empty());
}

TEST_CASE("scene: the timeline, dynamics and stiffness painting read with their values and resolved paths") {
  json j = squareArch();
  j["timeline"] = json::parse(R"({"fps": 30, "marks": [{"time": 0, "key": "arch", "ease": "hold"},
                                                       {"time": 2, "weights": {"square": 1, "arch": 1}}]})");
  j["dynamics"] = json::parse(R"({"epsilon": 0.4, "gravity": [0, 9.8], "mu": 1.5, "gust": 0.2})");
  j["stiffness"] = json::parse(R"({"range": [0.5, 8], "image": {"key": "arch", "path": "stiff.png"},
      "regions": [{"name": "head", "key": "square", "polygon": [[0, 0], [10, 0], [10, 10]], "kappa": 4}]})");
  const Scene s = parseScene(j.dump(), "scenes/square-arch.json");
  CHECK(s.timeline.fps() == 30);
  CHECK(s.timeline.weights(0) == Eigen::Vector2d(0, 1));
  CHECK(s.timeline.weights(2) == Eigen::Vector2d(0.5, 0.5));
  CHECK(s.timeline.segments()[0].easing.kind == EaseKind::kHold);
  CHECK(s.dynamics.epsilon == 0.4);
  CHECK(s.dynamics.gravity == Eigen::Vector2d(0, 9.8));
  CHECK(s.dynamics.mu == 1.5);
  CHECK(s.dynamics.gust == 0.2);
  CHECK(s.stiffness.soft == 0.5);
  CHECK(s.stiffness.stiff == 8);
  CHECK(s.stiffness.image == "scenes/stiff.png");
  CHECK(s.stiffness.imageKey == 1);
  REQUIRE(s.stiffness.regions.size() == 1);
  CHECK(s.stiffness.regions[0].key == 0);
  CHECK(s.stiffness.regions[0].kappa == 4);
}

TEST_CASE("scene: a key that does not place a cut's feature is named with the cut and the feature") {
  json j = squareArch();
  j["keys"][1]["features"].erase("split.tip");
  CHECK(messageOf(j) == "square-arch.json: cut \"split\": key \"arch\" does not place feature \"split.tip\"");
}

TEST_CASE("scene: every malformed or inconsistent field is an input error naming file, key and field") {
  const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
      {[](json& j) { j["colour"] = 1; }, "square-arch.json: unknown field \"colour\""},
      {[](json& j) { j["keys"][1]["feature"] = json::object(); }, "key \"arch\": unknown field \"feature\""},
      {[](json& j) { j["keys"][1]["colour"] = "red"; j["keys"][1].erase("name"); }, "key 2: unknown field \"colour\""},
      {[](json& j) { j["keys"][0]["cuts"][0]["width"] = 2; }, "key \"square\": cut \"split\": unknown field \"width\""},
      {[](json& j) { j["keys"][0]["cuts"][0].erase("name"); j["keys"][0]["cuts"][0]["nmae"] = "x"; },
       "key \"square\": cut 1: unknown field \"nmae\""},
      {[](json& j) { j["tracing"]["colour"] = 1; }, "tracing: unknown field \"colour\""},
      {[](json& j) { j["solver"]["colour"] = 1; }, "solver: unknown field \"colour\""},
      {[](json& j) { j["timeline"] = {{"marks", {{{"time", 0}, {"key", "square"}}, {{"time", 1}, {"key", "arch"}, {"easing", "linear"}}}}}; },
       "timeline: mark 2: unknown field \"easing\""},
      {[](json& j) { j["version"] = 2; }, "version: must be 1"},
      {[](json& j) { j["edge_length"] = -1; }, "edge_length: -1"},
      {[](json& j) { j["reference"] = "circle"; }, "reference: must name one of the keys"},
      {[](json& j) { j["solver"]["alpha"] = 1.5; }, "solver: alpha: 1.5 is out of range"},
      {[](json& j) { j["solver"]["tau"] = 0; }, "solver: tau: 0"},
      {[](json& j) { j["solver"]["metric"] = "harmonic"; }, "solver: metric: \"harmonic\" is not \"shared\""},
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
      {[](json& j) { j["keys"][1]["features"]["split.mouth"] = {1, 1}; },
       "key \"arch\": feature \"split.mouth\": names with a '.' are reserved for the features cuts create"},
      {[](json& j) { j["keys"][1]["features"]["gap.tip"] = {1, 1}; }, "and this scene has no cut \"gap\": rename it to \"gap-tip\""},
      {[](json& j) { j["keys"][1]["cuts"] = j["keys"][0]["cuts"]; }, "cut \"split\": is closed in every key"},
      {[](json& j) { j["keys"] = json::array(); }, "keys: needs at least one key"},
      {[](json& j) { j["timeline"] = {{"marks", {{{"time", 0}, {"key", "circle"}}}}}; },
       "timeline: mark 1: key: \"circle\" is not a key of this scene"},
      {[](json& j) { j["dynamics"] = {{"epsilon", 2}}; }, "dynamics: epsilon: 2"},
      {[](json& j) { j["dynamics"] = {{"gravity", 9.8}}; }, "dynamics: gravity: must be a point [x, y] in shape sizes"},
      {[](json& j) { j["dynamics"] = {{"drag", 1}}; }, "dynamics: unknown field \"drag\""},
      {[](json& j) { j["stiffness"] = {{"range", {5, 1}}}; }, "stiffness: range: needs 0 < soft < stiff"},
      {[](json& j) { j["stiffness"] = {{"image", {{"key", "arch"}}}}; }, "stiffness: image: missing field \"path\""},
      {[](json& j) { j["stiffness"] = {{"image", {{"key", "circle"}, {"path", "s.png"}}}}; },
       "stiffness: image: key: \"circle\" is not a key"},
      {[](json& j) { j["stiffness"] = {{"regions", {{{"name", "head"}, {"key", "arch"}, {"polygon", {{0, 0}, {1, 1}}}}}}}; },
       "stiffness: region \"head\": needs \"polygon\": at least 3 points"},
      {[](json& j) { j["stiffness"] = {{"regions", {{{"name", "head"}, {"key", "arch"}, {"colour", 1}}}}}; },
       "stiffness: region \"head\": unknown field \"colour\""},
      {[](json& j) { j["stiffness"] = {{"regions", {{{"key", "arch"}, {"colour", 1}}}}}; }, "stiffness: region 1: unknown field"},
      {[](json& j) { j["stiffness"] = {{"image", {{"key", "arch"}, {"colour", 1}}}}; }, "stiffness: image: unknown field \"colour\""},
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

TEST_CASE("scene: a dotted plain feature says dots are reserved for cut features and what to rename it to") {
  json j = squareArch();
  j["keys"][0]["features"]["a.b"] = {64, 24};
  j["keys"][1]["features"]["a.b"] = {64, 20};
  CHECK(messageOf(j) ==
        "square-arch.json: key \"square\": feature \"a.b\": names with a '.' are reserved for the features cuts create "
        "(CUT.left, CUT.right, CUT.tip for a notch named CUT; see docs/scene-format.md, \"Features and cuts\"), and this "
        "scene has no cut \"a\": rename it to \"a-b\" in every key that places it");
  json lip = squareArch();
  lip["keys"][1]["features"]["split.lip"] = {64, 20};
  CHECK(messageOf(lip).find("and cut \"split\" creates \"split.left\", \"split.right\", \"split.tip\" (did you mean "
                            "\"split.tip\"?): use one of those, or if \"split.lip\" is a plain feature, rename it to "
                            "\"split-lip\"") != std::string::npos);
}

TEST_CASE("scene: a one-key scene loads with a note that the animation is a still, two keys give no note") {
  json j = squareArch();
  CHECK(parseScene(j.dump(), "scenes/square-arch.json").notes.empty());
  j["keys"].erase(1);
  j["keys"][0].erase("cuts");
  const Scene scene = parseScene(j.dump(), "scenes/square-arch.json");
  REQUIRE(scene.notes.size() == 1);
  CHECK(scene.notes[0] == "square-arch.json: one key (\"square\"): the animation is a still, every frame that key's "
                          "drawing; add keys to animate");
}

TEST_CASE("scene: malformed JSON and a missing scene file are input errors naming the file") {
  CHECK_THROWS_WITH(parseScene("{\"version\": 1,", "bad.json"), Catch::StartsWith("bad.json: malformed JSON at line 1, column 15: "));
  // A comma missing between two points on line 3: the line, column and the text there.
  CHECK_THROWS_WITH(parseScene("{\n  \"version\": 1,\n  \"features\": {\"a\": [1, 2] \"b\": [3, 4]}\n}", "bad.json"),
                    Catch::StartsWith("bad.json: malformed JSON at line 3, column 30: syntax error while parsing object") &&
                        Catch::Contains("there the text reads `\"features\": {\"a\": [1, 2] \"b\"") &&
                        Catch::Contains("a missing or extra comma"));
  CHECK_THROWS_AS(loadScene("no-such-scene.json"), InputError);
  CHECK_THROWS_WITH(loadScene("no-such-scene.json"), Catch::Contains("no-such-scene.json"));
}

TEST_CASE("scene: a folder given as the scene is an input error naming the folder and the scene file inside") {
  const std::string folder = std::string(INBETWEEN_ASSETS) + "/square-hexagon";
  CHECK_THROWS_AS(loadScene(folder), InputError);
  CHECK_THROWS_WITH(loadScene(folder), Catch::Contains("is a folder") && Catch::Contains(folder + "/scene.json"));
  CHECK_THROWS_WITH(loadScene(INBETWEEN_ASSETS), Catch::Contains("is a folder, not a file"));
}

TEST_CASE("scene: cut features are named after the cut and the kind of its ends") {
  CHECK(cutFeatureNames("s", CutKind::kNotch) == std::vector<std::string>{"s.left", "s.right", "s.tip"});
  CHECK(cutFeatureNames("s", CutKind::kSplit).size() == 4);
  CHECK(cutFeatureNames("s", CutKind::kSlit) == std::vector<std::string>{"s.start", "s.end"});
}

TEST_CASE("scene: a misspelt or extra feature is blamed on the key that holds it, with the name meant") {
  // Three keys: "arch" and a copy "arch2" place "top"; the square misspells it.
  json j = squareArch();
  j["keys"].push_back(j["keys"][1]);
  j["keys"][2]["name"] = "arch2";
  j["keys"][0]["features"] = {{"tpo", {64, 24}}};
  CHECK(messageOf(j) == "square-arch.json: key \"square\": does not place feature \"top\" (keys \"arch\" and \"arch2\" do); "
                        "it places \"tpo\": did you mean \"top\"?");
  // One key places a feature no other does.
  j = squareArch();
  j["keys"].push_back(j["keys"][1]);
  j["keys"][2]["name"] = "arch2";
  j["keys"][1]["features"]["chin"] = {64, 100};
  CHECK(messageOf(j) == "square-arch.json: key \"arch\": places feature \"chin\", which keys \"square\" and \"arch2\" do not: "
                        "place it in every key, or in none");
  // Two keys: the first key's names are the ones meant.
  j = squareArch();
  j["keys"][1]["features"].erase("top");
  j["keys"][1]["features"]["Top"] = {64, 20};
  CHECK(messageOf(j) == "square-arch.json: key \"arch\": places feature \"Top\", which key \"square\" does not (did you "
                        "mean \"top\"?)");
}
