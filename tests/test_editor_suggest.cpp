// The editor's Suggest button under Xvfb with real X input (xdotool), on the drawn cat of
// tests/correspondence (its head and body the same in every key, its tail swinging, features on
// ears, paws and tail): clicked, it lists what the shape matching pairs between the features,
// with a confidence; Accept all places every suggestion in every key, on the key's outline, and
// the ones the matching found in place (the head's and feet's corners) at one point in all keys.
#include "editor/editor_session.h"
#include "editor/editor_view.h"
#include "play_fixtures.h"
#include "scene/scene_document.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

using namespace ib;
using namespace playtest;
namespace fs = std::filesystem;

namespace {

// The distance from p to the segment a-b (px).
double toSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// The distance from p to key k's traced outer outlines (px).
double offOutline(editor::EditorSession& session, int key, const Eigen::Vector2d& p) {
  double nearest = std::numeric_limits<double>::max();
  for (const Outline& outline : session.outlines(key))
    for (size_t i = 0; i < outline.outer.size(); ++i)
      nearest = std::min(nearest, toSegment(p, outline.outer[i], outline.outer[(i + 1) % outline.outer.size()]));
  return nearest;
}

}  // namespace

TEST_CASE("editor window: Suggest lists what the shape matching pairs between the cat's features, with a confidence; "
          "Accept all places each in every key, on its outline", "[window]") {
  const fs::path folder = fs::temp_directory_path() / "inbetween-editor-suggest-window";
  fs::remove_all(folder);
  fs::copy(fs::path(INBETWEEN_SOURCE_DIR) / "tests" / "correspondence" / "cat-tail", folder, fs::copy_options::recursive);
  const fs::path scene = folder / "scene.json";
  editor::EditorSession editing(SceneDocument::load(scene.string()));
  LiveWindow live(scene.string(), 1280, 800, &editing);
  editor::EditorView& view = *live.window->editor();
  live.send("mousemove --window 600 700");
  live.frames(3);
  const char* shots = std::getenv("INBETWEEN_SHOTS");

  clickControl(live, view, "Suggest features");
  live.frames(3);
  const std::vector<editor::FeatureSuggestion> suggested = view.suggestions();
  REQUIRE(suggested.size() >= 5);
  int inPlace = 0;
  for (const editor::FeatureSuggestion& s : suggested) {
    CHECK(s.confidence >= 0.3);  // from the matching, not the corner pairing (-1)
    CHECK(s.confidence <= 1);
    REQUIRE(s.at.size() == 3);
    inPlace += s.moved < 0.5;
  }
  CHECK(inPlace >= 5);  // the head's and feet's corners, drawn the same in every key
  const RgbaImage listed = live.shot("editor-suggest-listed");
  if (shots) writePng((fs::path(shots) / "editor-suggest-listed.png").string(), listed);

  const size_t before = editing.marks().keys[0].features.size();
  clickControl(live, view, "Accept all");
  live.frames(3);
  CHECK(view.suggestions().empty());
  for (int k = 0; k < 3; ++k) CHECK(editing.marks().keys[static_cast<size_t>(k)].features.size() == before + suggested.size());
  // Each accepted feature sits on every key's outline, where the suggestion put it; those found
  // in place are one point in all keys.
  for (const auto& [name, p] : editing.marks().keys[0].features) {
    if (name.rfind("corner", 0) != 0) continue;
    INFO(name);
    for (int k = 0; k < 3; ++k) CHECK(offOutline(editing, k, editing.marks().keys[static_cast<size_t>(k)].features.at(name)) < 1.0);
  }
  int samePlace = 0;
  for (const auto& [name, p] : editing.marks().keys[0].features)
    if (name.rfind("corner", 0) == 0)
      samePlace += (editing.marks().keys[1].features.at(name) - p).norm() < 0.5 && (editing.marks().keys[2].features.at(name) - p).norm() < 0.5;
  CHECK(samePlace == inPlace);
  const RgbaImage accepted = live.shot("editor-suggest-accepted");
  if (shots) writePng((fs::path(shots) / "editor-suggest-accepted.png").string(), accepted);
  // Each accepted suggestion is one undo step, in every key at once.
  live.send("key ctrl+z");
  live.frames(3);
  for (int k = 0; k < 3; ++k) CHECK(editing.marks().keys[static_cast<size_t>(k)].features.size() == before + suggested.size() - 1);
}
