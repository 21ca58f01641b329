// The editor's model without a window (editor/editor_marks.h, editor/editor_session.h): arcs
// coloured by the features they join, the same in every key, and red with a message naming the
// keys when the order differs; what to place next; snapping in the editor as `edit --apply` does.
#include "editor/editor_marks.h"
#include "editor/editor_session.h"
#include "editor/feature_suggestions.h"
#include "scene/scene_document.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

using namespace ib;
using namespace ib::editor;
namespace fs = std::filesystem;

namespace {

// A 100 x 100 square outline, traced as loops are (one orientation for every key).
std::vector<Outline> square() {
  Outline o;
  o.outer = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  return {o};
}

DocumentMarks twoKeys(const std::map<std::string, Eigen::Vector2d>& a, const std::map<std::string, Eigen::Vector2d>& b) {
  DocumentMarks marks;
  marks.keys.resize(2);
  marks.keys[0].name = "one";
  marks.keys[0].features = a;
  marks.keys[1].name = "two";
  marks.keys[1].features = b;
  marks.reference = "one";
  return marks;
}

}  // namespace

TEST_CASE("editor marks: the arc between two features has the same colour in every key, and another order turns it "
          "red with a message naming both keys") {
  const std::map<std::string, Eigen::Vector2d> abc = {{"a", {50, 0}}, {"b", {100, 50}}, {"c", {50, 100}}};
  std::map<std::pair<std::string, std::string>, int> colours;
  DocumentMarks same = twoKeys(abc, {{"a", {40, 0}}, {"b", {100, 70}}, {"c", {20, 100}}});
  std::vector<std::vector<OutlineArc>> arcs = {outlineArcs(square(), same.keys[0].features, colours),
                                               outlineArcs(square(), same.keys[1].features, colours)};
  REQUIRE(arcs[0].size() == 3);
  REQUIRE(arcs[1].size() == 3);
  CHECK(colours.size() == 3);  // three arcs, each met in both keys
  for (size_t i = 0; i < 3; ++i) {
    CHECK(arcs[0][i].from == arcs[1][i].from);
    CHECK(arcs[0][i].colour == arcs[1][i].colour);
    // Each arc starts and ends at its features.
    CHECK((arcs[0][i].points.front() - same.keys[0].features.at(arcs[0][i].from)).norm() < 1e-9);
    CHECK((arcs[0][i].points.back() - same.keys[0].features.at(arcs[0][i].to)).norm() < 1e-9);
  }
  CHECK(orderProblems(same, arcs).empty());

  // b and c swapped round the second key's outline.
  colours.clear();
  DocumentMarks swapped = twoKeys(abc, {{"a", {50, 0}}, {"c", {100, 50}}, {"b", {50, 100}}});
  arcs = {outlineArcs(square(), swapped.keys[0].features, colours), outlineArcs(square(), swapped.keys[1].features, colours)};
  const std::string message = orderProblems(swapped, arcs);
  CHECK(message.find("key `one`") != std::string::npos);
  CHECK(message.find("key `two`") != std::string::npos);
  int red = 0;
  for (const auto& key : arcs)
    for (const OutlineArc& arc : key) red += arc.unmatched;
  CHECK(red == 6);
}

TEST_CASE("editor marks: a feature some key lacks is asked for in the next key, and a cut's features only where the cut "
          "is open") {
  DocumentMarks marks = twoKeys({{"top", {50, 0}}}, {});
  marks.keys.push_back(KeyMarks{"three", "", {}, {}, {}, {}});
  std::vector<MissingFeature> missing = missingFeatures(marks, 0);
  REQUIRE(missing.size() == 2);
  CHECK(missing[0].feature == "top");
  CHECK(missing[0].key == "two");
  CHECK(missing[1].key == "three");
  CHECK(missingFeatures(marks, 1).front().key == "three");
  // A notch drawn in key one: its three features in the keys where it is open, never in one.
  marks.keys[1].features["top"] = {50, 0};
  marks.keys[2].features["top"] = {50, 0};
  marks.keys[0].cuts.push_back({"mouth", "notch", {{0, 50}, {40, 50}}});
  missing = missingFeatures(marks, 0);
  REQUIRE(missing.size() == 6);
  for (const MissingFeature& m : missing) CHECK(m.key != "one");
  CHECK(missing[0].feature == "mouth.left");
  CHECK(missing[2].feature == "mouth.tip");
}

TEST_CASE("editor session: a point near a key's outline snaps onto it as edit --apply snaps it, an edit and its undo "
          "each count as a change") {
  const fs::path scene = fs::path(INBETWEEN_ASSETS) / "square-arch-notch" / "scene.json";
  EditorSession session(SceneDocument::load(scene.string()));
  const int before = session.generation();
  const std::optional<Eigen::Vector2d> on = session.snap(0, {64, 25}, 8);
  REQUIRE(on);
  CHECK(std::abs(on->y() - 28) < 1.0);
  CHECK_FALSE(session.snap(0, {64, 10}, 8));
  session.apply(edit::SetFeature{"square", "top", *on});
  CHECK(session.generation() == before + 1);
  session.undo();
  CHECK(session.generation() == before + 2);
  CHECK(session.marks().keys[0].features.at("top") == Eigen::Vector2d(64, 28));
  CHECK(session.freshName("top") == "top1");
  CHECK(session.arcs(0).size() == 1);  // one feature: the whole loop, uncoloured
  CHECK(session.orderProblem().empty());
}

TEST_CASE("editor suggestions: the square's four corners are proposed with the arch's outer corners, each point on its "
          "key's outline") {
  const fs::path folder = fs::temp_directory_path() / "inbetween-editor-suggest";
  fs::remove_all(folder);
  fs::create_directories(folder);
  for (const char* png : {"square.png", "arch.png"})
    fs::copy_file(fs::path(INBETWEEN_ASSETS) / "square-arch-notch" / png, folder / png);
  std::ofstream(folder / "scene.json") << R"({"version": 1, "keys": [{"name": "square", "drawing": "square.png"},
                                                                      {"name": "arch", "drawing": "arch.png"}]})";
  EditorSession session(SceneDocument::load((folder / "scene.json").string()));
  const std::vector<std::vector<Outline>> outlines = {session.outlines(0), session.outlines(1)};
  const std::vector<FeatureSuggestion> suggested = suggestFeatures(session.marks(), outlines);
  REQUIRE(suggested.size() == 4);
  for (const FeatureSuggestion& s : suggested) {
    REQUIRE(s.at.size() == 2);
    CHECK(s.turn > 1.2);  // a square's corner turns 90 degrees
    for (int k = 0; k < 2; ++k) CHECK((nearestOnOutlines(outlines[static_cast<size_t>(k)], s.at[static_cast<size_t>(k)]) - s.at[static_cast<size_t>(k)]).norm() < 1e-6);
    // The square's corner and the arch's are the same corner: up-left goes with up-left.
    CHECK((s.at[0] - Eigen::Vector2d(64, 64)).normalized().dot((s.at[1] - Eigen::Vector2d(64, 64)).normalized()) > 0.95);
  }
}
