// The editor's window with more keys than fit side by side (stylized-walk's 16), under Xvfb with
// real X input (xdotool): one key large, the others as thumbnails; a click on a thumbnail shows
// that key large without editing it, a click on the large view's outline places a feature there,
// and the Edit tab's key list chooses the large key too.
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

// Key k's drawing width on screen, window px.
double shownWidth(editor::EditorView& view, int key, double drawingWidth) {
  return view.toScreen(key, {drawingWidth, 0}).x() - view.toScreen(key, {0, 0}).x();
}

}  // namespace

TEST_CASE("editor window: with 16 keys one is shown large and the others as thumbnails; a clicked thumbnail is shown large "
          "and takes a feature on its outline", "[window]") {
  const fs::path folder = fs::temp_directory_path() / "inbetween-editor-thumbnails";
  fs::remove_all(folder);
  fs::copy(fs::path(INBETWEEN_ASSETS) / "stylized-walk", folder, fs::copy_options::recursive);
  const fs::path scene = folder / "scene.json";
  editor::EditorSession editing(SceneDocument::load(scene.string()));
  REQUIRE(editing.keyCount() == 16);
  LiveWindow live(scene.string(), 1280, 720, &editing);
  editor::EditorView& view = *live.window->editor();
  live.send("mousemove --window 600 650");
  live.frames(3);
  const char* shots = std::getenv("INBETWEEN_SHOTS");
  const auto shot = [&](const std::string& name) {
    const RgbaImage image = live.shot("editor-thumbnails-" + name);
    if (shots) writePng((fs::path(shots) / ("editor-" + name + ".png")).string(), image);
  };

  // The reference key (k00) large, each other key at most a third of its width.
  REQUIRE(view.thumbnailLayout());
  CHECK(view.focusKey() == 0);
  const double large = shownWidth(view, 0, 512);
  CHECK(large > 300);
  for (int k = 1; k < 16; ++k) CHECK(shownWidth(view, k, 512) < large / 3);
  shot("thumbnails-start");

  // A click in k05's thumbnail shows it large, and places nothing.
  const size_t features = editing.marks().keys[5].features.size();
  live.send(at(view, 5, 256, 300) + " click 1");
  live.frames(3);
  CHECK(view.focusKey() == 5);
  CHECK(shownWidth(view, 5, 512) == Approx(large).margin(1.0));
  CHECK(shownWidth(view, 0, 512) < large / 3);
  CHECK(editing.marks().keys[5].features.size() == features);

  // A click on k05's outline, at its point farthest from the features it has, places a new
  // feature there (within a drawing pixel); the editor then asks for it in another key.
  Eigen::Vector2d target = Eigen::Vector2d::Zero();
  double farthest = -1;
  for (const Eigen::Vector2d& p : editing.outlines(5).at(0).outer) {
    double nearest = std::numeric_limits<double>::max();
    for (const auto& [name, q] : editing.marks().keys[5].features) nearest = std::min(nearest, (p - q).norm());
    if (nearest > farthest) farthest = nearest, target = p;
  }
  REQUIRE(farthest > 20);
  live.send(at(view, 5, target.x(), target.y()) + " click 1");
  live.frames(3);
  REQUIRE(editing.marks().keys[5].features.size() == features + 1);
  std::string added;
  for (const auto& [name, p] : editing.marks().keys[5].features)
    if (!editing.marks().keys[0].features.count(name)) added = name;
  REQUIRE(!added.empty());
  CHECK((editing.marks().keys[5].features.at(added) - target).norm() < 1.0);
  REQUIRE(editing.nextMissing(5));
  CHECK(editing.nextMissing(5)->feature == added);
  shot("thumbnails");

  // The key list in the Edit tab chooses the large key; Ctrl+Z takes the feature back.
  clickControl(live, view, "key 9");
  CHECK(view.focusKey() == 9);
  CHECK(shownWidth(view, 9, 512) == Approx(large).margin(1.0));
  live.send("key ctrl+z");
  live.frames(3);
  CHECK(editing.marks().keys[5].features.size() == features);
}
