// `inbetween edit --apply`'s operations (scene/edit_ops.h, pipeline/edit_script.h) on a scene
// document: every kind applies as the editor's edit of the same name, and undoing them all gives
// back the file byte for byte (redoing them, the edited file).
#include "core/atomic_file.h"
#include "core/error.h"
#include "pipeline/edit_script.h"
#include "scene/edit_ops.h"
#include "scene/scene_document.h"
#include "testkit/drawings.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

using namespace ib;

TEST_CASE("edit script: every kind of operation applies, and undoing them all restores the file, redoing them the "
          "edited one") {
  const std::filesystem::path chomp = std::filesystem::path(INBETWEEN_SOURCE_DIR) / "tests" / "topology" / "chomp";
  const std::string original = readFile((chomp / "scene.json").string());
  SceneDocument doc = SceneDocument::fromText(original, (chomp / "scene.json").string());
  REQUIRE_FALSE(doc.problem());
  const std::string ops = R"([
    {"op": "add_key", "name": "extra", "drawing": "closed.png"},
    {"op": "remove_key", "name": "extra"},
    {"op": "add_feature", "key": "closed", "name": "side", "at": [30, 128]},
    {"op": "add_feature", "key": "open", "name": "side", "at": [30, 128]},
    {"op": "move_feature", "key": "open", "name": "side", "at": [29, 131]},
    {"op": "rename_feature", "name": "side", "to": "back"},
    {"op": "remove_feature", "name": "back"},
    {"op": "add_interior_feature", "key": "closed", "name": "eye", "at": [128, 70], "radius": 5},
    {"op": "add_interior_feature", "key": "open", "name": "eye", "at": [128, 70]},
    {"op": "move_interior_feature", "key": "open", "name": "eye", "at": [127, 71]},
    {"op": "set_interior_radius", "name": "eye", "radius": 7},
    {"op": "remove_interior_feature", "name": "eye"},
    {"op": "add_cut", "key": "closed", "name": "slot", "kind": "slit", "points": [[100, 160], [150, 160]]},
    {"op": "remove_cut", "name": "slot"},
    {"op": "paint_stiffness", "key": "closed", "points": [[100, 100], [120, 100]], "radius": 10, "kappa": 2},
    {"op": "add_mark", "time": 0.25, "key": "open", "ease": "ease-out"},
    {"op": "move_mark", "index": 1, "time": 0.3},
    {"op": "set_mark_key", "index": 1, "key": "closed"},
    {"op": "set_mark_ease", "index": 1, "ease": "ease-in"},
    {"op": "set_reference", "key": "open"},
    {"op": "set_drawing", "key": "open", "drawing": "./open.png"},
    {"op": "set_cut_release", "cut": "mouth", "release": 0.4},
    {"op": "set", "name": "solver.tau", "value": 1e-4}
  ])";
  const std::vector<EditOp> read = readEditOps(ops, "ops.json");
  std::set<std::string> kinds;
  for (const EditOp& op : read) kinds.insert(op.op);
  CHECK(kinds.size() == editOpNames().size());  // every operation there is
  applyEditScript(doc, read, "ops.json");
  REQUIRE_FALSE(doc.problem());
  const std::string edited = doc.text();
  CHECK(edited != original);
  CHECK(doc.scene().timeline.marks().size() == 4);
  CHECK(doc.scene().timeline.marks()[1].time == Approx(0.3));
  CHECK(doc.scene().timeline.marks()[1].label == "closed");
  CHECK(doc.scene().reference == 1);
  CHECK(doc.scene().keys[0].cuts[0].release == Approx(0.4));
  CHECK(doc.parameter("solver.tau") == Approx(1e-4));
  int undone = 0;
  while (doc.canUndo()) doc.undo(), ++undone;
  CHECK(undone == static_cast<int>(read.size()));
  CHECK(doc.text() == original);
  while (doc.canRedo()) doc.redo();
  CHECK(doc.text() == edited);
}

TEST_CASE("edit script: a feature placed off its key's outline is refused with the distance and the nearest point, "
          "one within the snap distance lands on the outline") {
  const std::filesystem::path chomp = std::filesystem::path(INBETWEEN_SOURCE_DIR) / "tests" / "topology" / "chomp";
  SceneDocument doc = SceneDocument::load((chomp / "scene.json").string());
  const auto apply = [&](const std::string& ops) { applyEditScript(doc, readEditOps(ops, "ops.json"), "ops.json"); };
  // The disc's outline at the top is y = 28 (its ink's outer edge): 6 px above snaps, 12 px is refused.
  apply(R"([{"op": "move_feature", "key": "closed", "name": "top", "at": [128, 22]}])");
  CHECK(doc.scene().keys[0].features.at("top").y() == Approx(28).margin(1.5));
  try {
    apply(R"([{"op": "move_feature", "key": "closed", "name": "top", "at": [128, 16]}])");
    FAIL("a feature 12 px off the outline applied");
  } catch (const InputError& e) {
    const std::string message = e.what();
    CHECK(message.find("operation 0 (move_feature)") != std::string::npos);
    CHECK(message.find("px from key \"closed\"'s outline") != std::string::npos);
    CHECK(message.find("within 8 px") != std::string::npos);
  }
}

TEST_CASE("edit script: features snap onto the outline the mesher traces, a hole the artist marked on paper included") {
  // 128 px on white paper: an orange disc (r 45 at (64, 64)) with a white belly (r 18 at (64, 76))
  // that the scene marks a hole. Its rim is outline only with the hole point.
  RgbaImage drawing;
  drawing.width = drawing.height = 128;
  drawing.pixels.assign(128 * 128 * 4, 255);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const auto in = [&](double cx, double cy, double r) { return std::hypot(x + 0.5 - cx, y + 0.5 - cy) < r; };
      if (in(64, 64, 45) && !in(64, 76, 18)) {
        uint8_t* p = drawing.at(x, y);
        p[0] = 230, p[1] = 120, p[2] = 40;
      }
    }
  const std::string dir = test::scratchDirectory("edit-script-paper");
  writePng(dir + "/belly.png", drawing);
  std::ofstream(dir + "/scene.json") << R"({"version": 1, "keys": [
    {"name": "a", "drawing": "belly.png", "holes": [[64, 76]]},
    {"name": "b", "drawing": "belly.png", "holes": [[64, 76]]}]})";
  SceneDocument doc = SceneDocument::load(dir + "/scene.json");
  REQUIRE_FALSE(doc.problem());
  // 3 px inside the belly, below its top rim (y = 58); the disc's own outline is 39 px away.
  applyEditScript(doc, readEditOps(R"([{"op": "add_feature", "key": "a", "name": "belly", "at": [64, 61]},
                                       {"op": "add_feature", "key": "b", "name": "belly", "at": [64, 61]}])", "ops.json"),
                  "ops.json");
  CHECK(doc.scene().keys[0].features.at("belly").y() == Approx(58).margin(1.5));
}

TEST_CASE("edit script: set_interior_radius sets the radius in every key that gives one, else in the first key that "
          "places the feature; out of range is refused naming it") {
  const std::filesystem::path chomp = std::filesystem::path(INBETWEEN_SOURCE_DIR) / "tests" / "topology" / "chomp";
  SceneDocument doc = SceneDocument::load((chomp / "scene.json").string());
  const auto apply = [&](const std::string& ops) { applyEditScript(doc, readEditOps(ops, "ops.json"), "ops.json"); };
  apply(R"([{"op": "add_interior_feature", "key": "closed", "name": "eye", "at": [128, 70]},
            {"op": "add_interior_feature", "key": "open", "name": "eye", "at": [128, 70]},
            {"op": "set_interior_radius", "name": "eye", "radius": 6}])");
  REQUIRE_FALSE(doc.problem());
  CHECK(doc.scene().keys[1].interiorRadii.at("eye") == Approx(6));  // given once, it is every key's
  const nlohmann::json json = nlohmann::json::parse(doc.json());
  CHECK(json["keys"][0]["interior_features"]["eye"]["radius"] == 6);
  CHECK(json["keys"][1]["interior_features"]["eye"].is_array());  // the open key's stays a point
  apply(R"([{"op": "add_interior_feature", "key": "open", "name": "eye", "at": [128, 70], "radius": 6},
            {"op": "set_interior_radius", "name": "eye", "radius": 9}])");
  REQUIRE_FALSE(doc.problem());
  CHECK(doc.scene().keys[0].interiorRadii.at("eye") == Approx(9));
  CHECK(doc.scene().keys[1].interiorRadii.at("eye") == Approx(9));
  const std::string before = doc.text();
  CHECK_THROWS_WITH(apply(R"([{"op": "set_interior_radius", "name": "eye", "radius": 5000}])"),
                    Catch::Contains("ops.json") && Catch::Contains("interior feature \"eye\": radius 5000 px is out of range"));
  CHECK_THROWS_WITH(apply(R"([{"op": "set_interior_radius", "name": "ear", "radius": 5}])"), Catch::Contains("no interior feature \"ear\""));
  CHECK(doc.text() == before);
  // Written as an object without a radius: the radius joins it.
  nlohmann::json root = nlohmann::json::parse(doc.json());
  for (auto& key : root["keys"]) key["interior_features"]["ear"] = {{"at", {100, 90}}};
  SceneDocument objects = SceneDocument::fromText(root.dump(), (chomp / "scene.json").string());
  REQUIRE_FALSE(objects.problem());
  applyEditScript(objects, readEditOps(R"([{"op": "set_interior_radius", "name": "ear", "radius": 4}])", "ops.json"), "ops.json");
  REQUIRE_FALSE(objects.problem());
  const nlohmann::json after = nlohmann::json::parse(objects.json());
  CHECK(after["keys"][0]["interior_features"]["ear"] == nlohmann::json({{"at", {100, 90}}, {"radius", 4}}));
  CHECK(after["keys"][1]["interior_features"]["ear"] == nlohmann::json({{"at", {100, 90}}}));
}
