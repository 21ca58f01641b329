// `inbetween edit --apply`'s operations (scene/edit_ops.h, pipeline/edit_script.h) on a scene
// document: every kind applies as the editor's edit of the same name, and undoing them all gives
// back the file byte for byte (redoing them, the edited file).
#include "core/atomic_file.h"
#include "core/error.h"
#include "pipeline/edit_script.h"
#include "scene/edit_ops.h"
#include "scene/scene_document.h"

#include <catch2/catch.hpp>
#include <filesystem>
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
    {"op": "remove_interior_feature", "name": "eye"},
    {"op": "add_cut", "key": "closed", "name": "slot", "kind": "slit", "points": [[100, 160], [150, 160]]},
    {"op": "remove_cut", "name": "slot"},
    {"op": "paint_stiffness", "key": "closed", "points": [[100, 100], [120, 100]], "radius": 10, "kappa": 2},
    {"op": "add_mark", "time": 0.25, "key": "open", "ease": "ease-out"},
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
