// The scene document (solver/scene/scene_document.h): typed edits, validation naming key and
// field, undo and redo, and a writer that keeps the file's layout.
#include "scene/scene_document.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/parameters.h"
#include "testkit/drawings.h"
#include "testkit/errors.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <functional>
#include <random>
#include <sstream>

using namespace ib;
namespace fs = std::filesystem;

using ::test::inputError;

namespace {

std::string asset(const std::string& name) { return std::string(INBETWEEN_ASSETS) + "/" + name + "/scene.json"; }

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

// Lines of `after` not in `before` at the same place, for texts of the same line count; -1 when
// the counts differ.
int changedLines(const std::string& before, const std::string& after) {
  const std::vector<std::string> a = lines(before), b = lines(after);
  if (a.size() != b.size()) return -1;
  int changed = 0;
  for (size_t i = 0; i < a.size(); ++i) changed += a[i] != b[i];
  return changed;
}


std::vector<std::string> bundledScenes() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(INBETWEEN_ASSETS))
    if (fs::exists(entry.path() / "scene.json")) files.push_back((entry.path() / "scene.json").string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("scene document: every bundled scene written back unedited is its file, byte for byte, and valid") {
  const std::vector<std::string> files = bundledScenes();
  REQUIRE(files.size() >= 20);
  for (const std::string& file : files) {
    INFO(file);
    const SceneDocument document = SceneDocument::load(file);
    CHECK(document.text() == readFile(file));
    CHECK_FALSE(document.problem());
    CHECK_FALSE(document.modified());
    CHECK(document.scene().keys.size() == loadScene(file).keys.size());
  }
}

TEST_CASE("scene document: moving a feature changes one line, and undo and redo restore the texts byte for byte") {
  SceneDocument document = SceneDocument::load(asset("square-arch-notch"));
  const std::string original = document.text();
  document.apply(edit::SetFeature{"arch", "top", {64, 22.5}});
  CHECK(document.scene().keys[1].features.at("top") == Eigen::Vector2d(64, 22.5));
  CHECK(changedLines(original, document.text()) == 1);
  CHECK_THAT(document.text(), Catch::Contains("\"top\": [64, 22.5]"));
  CHECK(document.modified());
  CHECK(document.undoLabel() == "place feature \"top\" in key \"arch\"");
  const std::string moved = document.text();
  document.undo();
  CHECK(document.text() == original);
  CHECK_FALSE(document.modified());
  CHECK(document.canRedo());
  document.redo();
  CHECK(document.text() == moved);
  CHECK_FALSE(document.canRedo());
}

TEST_CASE("scene document: renaming a key, a feature or a cut renames every use, and the scene stays valid") {
  SceneDocument document = SceneDocument::load(asset("square-arch-notch"));
  document.apply(edit::RenameKey{"square", "box"});
  CHECK_FALSE(document.problem());
  CHECK(document.scene().keys[document.scene().reference].name == "box");
  CHECK(document.scene().timeline.marks().front().label == "box");
  document.apply(edit::RenameFeature{"top", "crown"});
  CHECK(document.scene().keys[0].features.count("crown") == 1);
  CHECK(document.scene().keys[1].features.count("crown") == 1);
  document.apply(edit::RenameCut{"split", "mouth"});
  CHECK_FALSE(document.problem());
  CHECK(document.scene().keys[0].cuts.at(0).name == "mouth");
  CHECK(document.scene().keys[1].features.count("mouth.tip") == 1);
  // The rename of a key is one edit: one undo takes back every use.
  document.undo();
  document.undo();
  document.undo();
  CHECK(document.text() == readFile(asset("square-arch-notch")));
}

TEST_CASE("scene document: a feature placed in one key only is a problem naming the key, until the other places it") {
  SceneDocument document = SceneDocument::load(asset("square-arch-notch"));
  document.apply(edit::SetFeature{"square", "chin", {64, 100}});
  REQUIRE(document.problem());
  CHECK_THAT(*document.problem(), Catch::Contains("key \"arch\"") && Catch::Contains("does not place feature \"chin\""));
  CHECK_THROWS_AS(document.scene(), InputError);
  document.apply(edit::SetFeature{"arch", "chin", {64, 108}});
  CHECK_FALSE(document.problem());
  CHECK(document.scene().keys[1].features.at("chin") == Eigen::Vector2d(64, 108));
}

TEST_CASE("scene document: an edit that cannot apply changes nothing and says what is wrong") {
  SceneDocument document = SceneDocument::load(asset("square-arch-notch"));
  const std::string original = document.text();
  CHECK_THAT(inputError([&] { document.apply(edit::SetFeature{"sqare", "top", {1, 2}}); }),
             Catch::Contains("no key \"sqare\"") && Catch::Contains("did you mean \"square\""));
  CHECK_THAT(inputError([&] { document.apply(edit::RenameKey{"square", "arch"}); }), Catch::Contains("exists already"));
  CHECK_THAT(inputError([&] { document.apply(edit::RemoveCutPoint{"square", "split", 0}); }),
             Catch::Contains("at least 2 points"));
  CHECK_THAT(inputError([&] { document.apply(edit::MoveCutPoint{"square", "split", 5, {1, 1}}); }),
             Catch::Contains("point 6 is not one of 1..2"));
  CHECK_THAT(inputError([&] { document.apply(edit::MoveMark{1, 3}); }), Catch::Contains("stays between its neighbours"));
  CHECK_THAT(inputError([&] { document.apply(edit::SetParameter{"tau", 0}); }), Catch::Contains("(0, 1e+06]"));
  CHECK_THAT(inputError([&] { document.apply(edit::AddCut{"square", "a.b", "notch", {{1, 1}, {2, 2}}}); }),
             Catch::Contains("reserved"));
  CHECK_THAT(inputError([&] { document.apply(edit::AddMark{1.0000004, "square"}); }), Catch::Contains("mark 2 is at 1 s already"));
  CHECK_THAT(inputError([&] { document.setFromText("tua=1"); }), Catch::Contains("did you mean \"tau\""));
  CHECK_THAT(inputError([&] { document.setFromText("kappa_scale=2"); }), Catch::Contains("player's own"));
  CHECK(document.text() == original);
  CHECK_FALSE(document.canUndo());
}

TEST_CASE("scene document: cut, hole, stiffness and mark edits reach the scene") {
  SceneDocument document = SceneDocument::load(asset("square-arch-notch"));
  document.apply(edit::InsertCutPoint{"square", "split", 1, {64, 80}});
  document.apply(edit::MoveCutPoint{"square", "split", 2, {64, 60}});
  CHECK(document.scene().keys[0].cuts[0].points.size() == 3);
  CHECK(document.scene().keys[0].cuts[0].points[2] == Eigen::Vector2d(64, 60));
  document.apply(edit::RemoveCutPoint{"square", "split", 1});
  CHECK(document.scene().keys[0].cuts[0].points.size() == 2);

  document.apply(edit::AddStiffnessRegion{"head", "square", {{20, 20}, {108, 20}, {108, 50}}, 4});
  document.apply(edit::AddStiffnessStroke{"spine", "arch", {{64, 20}, {64, 60}}, 6, 0.5});
  document.apply(edit::MoveStiffnessPoint{"spine", 1, {64, 70}});
  document.apply(edit::SetStiffnessKappa{"head", 8});
  REQUIRE(document.scene().stiffness.regions.size() == 1);
  CHECK(document.scene().stiffness.regions[0].kappa == 8);
  REQUIRE(document.scene().stiffness.strokes.size() == 1);
  CHECK(document.scene().stiffness.strokes[0].key == 1);
  CHECK(document.scene().stiffness.strokes[0].points[1] == Eigen::Vector2d(64, 70));
  CHECK(document.scene().stiffness.strokes[0].radius == 6);
  document.apply(edit::ScaleStiffness{2});
  CHECK(document.scene().stiffness.regions[0].kappa == 16);
  CHECK(document.scene().stiffness.strokes[0].kappa == 1);
  CHECK(document.scene().kappa == 2);
  document.apply(edit::RenameStiffness{"spine", "back"});
  document.apply(edit::RemoveStiffness{"head"});
  CHECK(document.scene().stiffness.regions.empty());
  CHECK(document.scene().stiffness.strokes.at(0).name == "back");

  document.apply(edit::AddMark{0.5, "", {{"square", 1}, {"arch", 1}}});
  REQUIRE(document.scene().timeline.marks().size() == 4);
  CHECK(document.scene().timeline.marks()[1].weights == Eigen::Vector2d(0.5, 0.5));
  document.apply(edit::MoveMark{1, 0.25});
  CHECK(document.scene().timeline.marks()[1].time == 0.25);
  document.apply(edit::SetMarkKey{1, "arch"});
  CHECK(document.scene().timeline.marks()[1].label == "arch");
  document.apply(edit::RemoveMark{1});
  CHECK(document.scene().timeline.marks().size() == 3);
  CHECK_FALSE(document.problem());
}

TEST_CASE("scene document: a scene without marks gets its timeline's marks written out at the first mark edit") {
  SceneDocument document = SceneDocument::load(asset("pentagon-star"));
  REQUIRE(document.text().find("\"marks\"") == std::string::npos);
  const std::vector<TimelineMark> before = document.scene().timeline.marks();
  document.apply(edit::AddMark{before.back().time + 1, before.front().label});
  const std::vector<TimelineMark> after = document.scene().timeline.marks();
  REQUIRE(after.size() == before.size() + 1);
  for (size_t i = 0; i < before.size(); ++i) {
    CHECK(after[i].time == before[i].time);
    CHECK(after[i].weights == before[i].weights);
  }
}

TEST_CASE("scene document: adding, moving and removing keys and interior features") {
  SceneDocument document = SceneDocument::load(asset("square-arch-notch"));
  document.apply(edit::AddKey{"blob", "arch.png", 1});
  REQUIRE(document.problem());  // it places none of the features yet
  CHECK_THAT(*document.problem(), Catch::Contains("key \"blob\""));
  document.apply(edit::RemoveKey{"blob"});
  CHECK_FALSE(document.problem());
  document.apply(edit::MoveKey{"arch", 0});
  CHECK(document.scene().keys[0].name == "arch");
  document.apply(edit::SetInteriorFeature{"square", "eye", {50, 50}, 4});
  document.apply(edit::SetInteriorFeature{"arch", "eye", {50, 40}, std::nullopt});
  CHECK(document.scene().keys[1].interiorRadii.at("eye") == 4);  // one radius, given in one key
  document.apply(edit::RenameInteriorFeature{"eye", "nose"});
  CHECK(document.scene().keys[0].interiorFeatures.count("nose") == 1);
  document.apply(edit::RemoveInteriorFeature{"nose", ""});
  CHECK(document.scene().keys[0].interiorFeatures.empty());
  document.apply(edit::AddHole{"square", {60, 60}});
  document.apply(edit::MoveHole{"square", 0, {61, 60}});
  CHECK(document.scene().keys[1].holes.at(0) == Eigen::Vector2d(61, 60));
  document.apply(edit::RemoveHole{"square", 0});
  CHECK(document.scene().keys[1].holes.empty());
}

TEST_CASE("scene document: parameters set from text as --set gives them, and reset to the default") {
  SceneDocument document = SceneDocument::load(asset("square-arch-notch"));
  const std::string original = document.text();
  document.setFromText("tau=1e-9");
  CHECK(document.scene().interpolation.cohesive.tau == 1e-9);
  CHECK(document.parameter("tau") == 1e-9);
  document.setFromText("metric=per_key");
  CHECK(document.scene().interpolation.metric == ShapeMetric::kPerKey);
  document.setFromText("gravity_y=2.5");
  CHECK(document.scene().dynamics.gravity == Eigen::Vector2d(0, 2.5));
  document.apply(edit::ResetParameter{"tau"});
  document.apply(edit::ResetParameter{"metric"});
  document.apply(edit::ResetParameter{"gravity_y"});
  CHECK(document.scene().interpolation.cohesive.tau == parameter("tau").defaultValue);
  CHECK(nlohmann::json::parse(document.text()) == nlohmann::json::parse(original));
}

TEST_CASE("scene document: save writes the text atomically, and the file loads as the document's scene") {
  const std::string dir = test::scratchDirectory("scene-document-save");
  const std::string file = (fs::path(dir) / "scene.json").string();
  writeFileAtomically(file, readFile(asset("square-arch-notch")));
  for (const char* drawing : {"square.png", "arch.png"})
    fs::copy_file(fs::path(INBETWEEN_ASSETS) / "square-arch-notch" / drawing, fs::path(dir) / drawing);
  SceneDocument document = SceneDocument::load(file);
  document.apply(edit::SetFeature{"square", "top", {64, 30}});
  document.setFromText("alpha=0.25");
  document.save();
  CHECK_FALSE(document.modified());
  CHECK(readFile(file) == document.text());
  const Scene reloaded = loadScene(file);
  CHECK(reloaded.keys[0].features.at("top") == Eigen::Vector2d(64, 30));
  CHECK(reloaded.interpolation.cohesive.alpha == 0.25);
  for (const auto& entry : fs::directory_iterator(dir)) CHECK(entry.path().extension() != ".tmp");
}

TEST_CASE("scene document: random edits on every bundled scene keep the text parsing to the document, and undoing all restores the file") {
  std::mt19937 random(45);
  for (const std::string& file : bundledScenes()) {
    INFO(file);
    SceneDocument document = SceneDocument::load(file);
    const std::string original = document.text();
    const Scene scene = document.scene();
    int applied = 0;
    for (int step = 0; step < 40; ++step) {
      const KeySpec& key = scene.keys[random() % scene.keys.size()];
      const Eigen::Vector2d p(double(random() % 2000) / 10, double(random() % 2000) / 10);
      const std::vector<std::function<void()>> edits = {
          [&] {
            if (!key.features.empty()) document.apply(edit::SetFeature{key.name, key.features.begin()->first, p});
          },
          [&] { document.setFromText("tau=" + std::to_string(1e-6 * (1 + random() % 1000))); },
          [&] { document.setFromText("gravity_x=" + std::to_string(int(random() % 7) - 3)); },
          [&] { document.apply(edit::AddHole{key.name, p}); },
          [&] {
            if (!key.cuts.empty()) document.apply(edit::MoveCutPoint{key.name, key.cuts[0].name, 0, p});
          },
          [&] { document.apply(edit::AddStiffnessStroke{"s" + std::to_string(step), key.name, {p}, 5, 2}); },
      };
      edits[random() % edits.size()]();
      ++applied;
      REQUIRE(nlohmann::ordered_json::parse(document.text()) == nlohmann::ordered_json::parse(document.json()));
    }
    while (document.canUndo()) document.undo();
    CHECK(document.text() == original);
    CHECK(applied == 40);
  }
}
