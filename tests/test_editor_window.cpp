// The editor's window (`inbetween edit`) under Xvfb, driven by real X input (xdotool): a new
// scene made from square-arch-notch's two drawings gets a feature clicked onto both outlines, the
// feature dragged along one, a notch cut drawn with its three features placed where it is open,
// an interior feature with a dragged radius (its rim dragged again), a painted stiffness stroke,
// undo, and Ctrl+S; the saved scene then meshes and renders with `inbetween`. Screenshots (the temporary folder) show
// the coloured arcs and labels, and are measured.
#include "editor/editor_session.h"
#include "editor/editor_view.h"
#include "pipeline/cut_timing.h"
#include "play_fixtures.h"
#include "scene/scene.h"
#include "scene/scene_document.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

using namespace ib;
using namespace playtest;
namespace fs = std::filesystem;

namespace {

constexpr int kEditWidth = 1280, kEditHeight = 800;

// A scene of square-arch-notch's drawings, no annotations, as `inbetween new` writes it.
fs::path newScene(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("inbetween-editor-" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  for (const char* png : {"square.png", "arch.png"})
    fs::copy_file(fs::path(INBETWEEN_ASSETS) / "square-arch-notch" / png, folder / png);
  const fs::path scene = folder / "scene.json";
  const test::CommandRun run = inbetween("new " + scene.string() + " " + (folder / "square.png").string() + " " +
                                         (folder / "arch.png").string() + " --no-window");
  REQUIRE(run.code == 0);
  return scene;
}

// Draws a two-point cut in key k with real input: the Cut tool (C), a click at each end, Enter.
void drawCut(LiveWindow& live, editor::EditorView& view, int key, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  live.send("key c");
  live.frames(2);
  live.send(at(view, key, from.x(), from.y()) + " click 1");
  live.frames(3);
  live.send(at(view, key, to.x(), to.y()) + " click 1");
  live.frames(3);
  live.send("key Return");
  live.frames(3);
}

// With the Interior tool: a press at (x, y) in key k, a drag of `radius` drawing px to the right, a release.
void dragInterior(LiveWindow& live, editor::EditorView& view, int key, double x, double y, double radius) {
  live.send(at(view, key, x, y) + " mousedown 1");
  live.frames(3);
  live.send(at(view, key, x + radius, y));
  live.frames(3);
  live.send("mouseup 1");
  live.frames(3);
}

// Renames through the Edit tab as a user does: a click in the field (which selects its text), the
// new name typed on the keyboard, a click on the field's button.
void renameThroughPanel(LiveWindow& live, editor::EditorView& view, const std::string& field, const std::string& button,
                        const std::string& to) {
  clickControl(live, view, field);
  live.sendWhilePresenting("type --delay 40 " + to);  // frames between the keys: ImGui takes a key a frame
  live.frames(static_cast<int>(to.size()));           // and the keys a slow frame left queued
  clickControl(live, view, button);
}

// Pixels of window rows [y0, y1) and columns [x0, x1) within 40/255 of an RGB colour.
int colourCount(const RgbaImage& shot, int x0, int y0, int x1, int y1, int r, int g, int b) {
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const uint8_t* p = &shot.pixels[4 * (static_cast<size_t>(y) * shot.width + x)];
      if (std::abs(p[0] - r) <= 40 && std::abs(p[1] - g) <= 40 && std::abs(p[2] - b) <= 40) ++count;
    }
  return count;
}

}  // namespace

TEST_CASE("editor window: features clicked onto two keys' outlines, dragged, a cut with its features, an interior "
          "feature, paint, undo and save make a scene that meshes and renders", "[window]") {
  const fs::path scene = newScene("window");
  editor::EditorSession editing(SceneDocument::load(scene.string()));
  LiveWindow live(scene.string(), kEditWidth, kEditHeight, &editing);
  editor::EditorView& view = *live.window->editor();
  const auto feature = [&](const std::string& key, const std::string& name) -> std::optional<Eigen::Vector2d> {
    const int k = editing.marks().keyIndex(key);
    if (k < 0 || !editing.marks().keys[static_cast<size_t>(k)].features.count(name)) return std::nullopt;
    return editing.marks().keys[static_cast<size_t>(k)].features.at(name);
  };

  // A click 4 window px above the square's top edge snaps onto it; the editor then asks for the
  // same feature in the arch, and the next click there places it.
  live.send(at(view, 0, 64, 28, 0, -4) + " click 1");
  live.frames(4);
  REQUIRE(feature("square", "f1"));
  CHECK(std::abs(feature("square", "f1")->y() - 28) < 1.0);
  REQUIRE(editing.nextMissing(0));
  CHECK(editing.nextMissing(0)->feature == "f1");
  CHECK(editing.nextMissing(0)->key == "arch");
  live.send(at(view, 1, 64, 20, 3, -3) + " click 1");
  live.frames(4);
  REQUIRE(feature("arch", "f1"));
  CHECK(std::abs(feature("arch", "f1")->y() - 20) < 1.0);
  CHECK_FALSE(editing.document().problem());
  // A second feature on the other side, in both keys: the outline is in two coloured arcs.
  live.send(at(view, 0, 28, 64, -3, 0) + " click 1");
  live.frames(3);
  live.send(at(view, 1, 20, 64, -3, 0) + " click 1");
  live.frames(3);
  REQUIRE(feature("square", "f2"));
  REQUIRE(feature("arch", "f2"));

  // Drag the square's f1 along the outline, 20 drawing px to the right.
  live.send(at(view, 0, 64, 28) + " mousedown 1");
  live.frames(3);
  live.send(at(view, 0, 74, 27));
  live.frames(3);
  live.send(at(view, 0, 84, 26));
  live.frames(3);
  live.send("mouseup 1");
  live.frames(4);
  REQUIRE(feature("square", "f1"));
  CHECK(feature("square", "f1")->x() == Approx(84).margin(1.0));
  CHECK(std::abs(feature("square", "f1")->y() - 28) < 1.0);

  // A notch cut in the square (C, two clicks, Enter), then its three features
  // where it is open, in the arch, as the editor asks for them.
  drawCut(live, view, 0, {64, 100}, {64, 64});
  std::string messages;
  for (const auto& m : live.session.messages()) messages += m.text + "\n";
  INFO(messages);
  REQUIRE(editing.marks().keys[0].cuts.size() == 1);
  CHECK(editing.marks().keys[0].cuts[0].kind == "notch");
  live.send("key q");
  live.frames(2);
  for (const auto& [name, x, y] : {std::tuple<const char*, double, double>{"cut1.left", 46, 108}, {"cut1.right", 82, 108}, {"cut1.tip", 64, 56}}) {
    REQUIRE(editing.nextMissing(0));
    CHECK(editing.nextMissing(0)->feature == name);
    live.send(at(view, 1, x, y) + " click 1");
    live.frames(3);
    CHECK(feature("arch", name));
  }
  INFO((editing.document().problem() ? *editing.document().problem() : std::string()));
  CHECK_FALSE(editing.document().problem());

  // An interior feature with a radius dragged out to 6 px, in both keys.
  live.send("key d");
  live.frames(2);
  dragInterior(live, view, 0, 48, 46, 6);
  dragInterior(live, view, 1, 40, 40, 6);
  REQUIRE(editing.marks().keys[0].interior.count("detail1"));
  REQUIRE(editing.marks().keys[1].interior.count("detail1"));
  CHECK(editing.marks().keys[0].radii.at("detail1") == Approx(6).margin(1.0));
  // Its rim dragged out by 3 px in the second key: the radius changes in both.
  dragInterior(live, view, 1, 46, 40, 3);
  CHECK(editing.marks().keys[0].radii.at("detail1") == Approx(9).margin(1.0));
  CHECK(editing.marks().keys[1].radii.at("detail1") == Approx(9).margin(1.0));
  CHECK(editing.marks().keys[1].interior.at("detail1").x() == Approx(40).margin(1.0));  // the point stays
  // The Edit tab's Undo and Redo buttons, clicked.
  for (const char* button : {"Undo", "Redo"}) {
    clickControl(live, view, button);
    CHECK(editing.marks().keys[1].radii.at("detail1") == Approx(std::string(button) == "Undo" ? 6 : 9).margin(1.0));
  }

  // A second interior feature too near the square's outline: the rebuild fails, its message names
  // the feature, the last good animation stays; undone, the next build clears the message.
  REQUIRE(presentUntil(*live.window, [&] { return !live.session.reloader().busy() && !view.awaitingFrame(); }, 60));
  const int builtVertices = live.session.renderMesh().vertexCount;
  for (int k = 0; k < 2; ++k) {
    live.send(at(view, k, k == 0 ? 31 : 23, 64) + " click 1");
    live.frames(3);
  }
  REQUIRE(presentUntil(*live.window, [&] { return !view.buildError().empty(); }, 60));
  CHECK(view.buildError().find("detail2") != std::string::npos);
  CHECK(live.session.renderMesh().vertexCount == builtVertices);
  live.send("key ctrl+z");
  live.frames(2);
  live.send("key ctrl+z");
  REQUIRE(presentUntil(*live.window, [&] { return view.buildError().empty() && !live.session.reloader().busy(); }, 60));
  CHECK_FALSE(editing.marks().keys[0].interior.count("detail2"));

  // A stiffness stroke painted across the square (the reference), then undone and redone.
  live.send("key b");
  live.frames(2);
  live.send(at(view, 0, 40, 50) + " mousedown 1");
  live.frames(3);
  for (int x = 50; x <= 90; x += 10) {
    live.send(at(view, 0, x, 50));
    live.frames(2);
  }
  live.send("mouseup 1");
  live.frames(3);
  REQUIRE(editing.marks().strokes.size() == 1);
  CHECK(editing.marks().strokes[0].key == "square");
  CHECK(editing.marks().strokes[0].points.size() >= 3);
  live.send("key ctrl+z");
  live.frames(3);
  CHECK(editing.marks().strokes.empty());
  live.send("key ctrl+shift+z");
  live.frames(3);
  CHECK(editing.marks().strokes.size() == 1);

  // The picture: the arc from f2 to f1 (no cut between them) has the same colour in both keys
  // (the palette's second, green), the square's arc from f1 round to f2 the first (crimson); the
  // arch's cut features split that one into arcs of their own. Red (features out of order) nowhere.
  live.send("key q mousemove --window 900 700");
  live.frames(3);
  const RgbaImage shot = live.shot("editor-marks");
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d a = view.toScreen(k, {0, 0}), b = view.toScreen(k, {128, 128});
    const int x0 = static_cast<int>(a.x()), y0 = static_cast<int>(a.y()), x1 = static_cast<int>(b.x()), y1 = static_cast<int>(b.y());
    INFO("key " << k);
    if (k == 0) CHECK(colourCount(shot, x0, y0, x1, y1, 230, 25, 75) > 100);  // palette 0
    CHECK(colourCount(shot, x0, y0, x1, y1, 60, 180, 75) > 100);              // palette 1, in both
    CHECK(colourCount(shot, x0, y0, x1, y1, 255, 0, 0) == 0);
  }
  CHECK(live.window->ui().width == kEditWidth);
  CHECK(view.title().find(" *") != std::string::npos);

  // The timeline: the arch's mark (mark 2, at 1 s = frame 24) dragged to frame 30 in time, and
  // the cut's release marker dragged: its release becomes the open keys' weight at the drop.
  live.frames(10);
  const play::TimelineEditing& timeline = live.window->ui().timelineEditing;
  const int frameCount = live.session.transport().frameCount();
  const auto xOf = [&](double frame) { return static_cast<int>(std::lround(timeline.x0 + frame / (frameCount - 1) * timeline.width)); };
  live.send("mousemove --window " + std::to_string(xOf(24)) + " " + std::to_string(static_cast<int>(timeline.markY)) + " mousedown 1");
  live.frames(3);
  live.send("mousemove --window " + std::to_string(xOf(27)) + " " + std::to_string(static_cast<int>(timeline.markY)));
  live.frames(3);
  live.send("mousemove --window " + std::to_string(xOf(30)) + " " + std::to_string(static_cast<int>(timeline.markY)) + " mouseup 1");
  live.frames(4);
  CHECK(editing.document().scene().timeline.marks()[1].time == Approx(30.0 / 24));
  CHECK(view.selectedMark() == 1);
  // The release marker: wait for the rebuilt scene, then drag the first one (it lets go) 3 frames on.
  REQUIRE(presentUntil(*live.window, [&] { return !live.session.reloader().busy() && !live.session.cutEvents().empty(); }, 60));
  live.frames(3);
  const CutEvent letGo = live.session.cutEvents().front();
  live.send("mousemove --window " + std::to_string(xOf(letGo.frame)) + " " + std::to_string(static_cast<int>(timeline.cutY)) + " mousedown 1");
  live.frames(3);
  live.send("mousemove --window " + std::to_string(xOf(letGo.frame + 3)) + " " + std::to_string(static_cast<int>(timeline.cutY)) + " mouseup 1");
  live.frames(4);
  REQUIRE(editing.document().scene().keys[0].cuts[0].release);
  CHECK(*editing.document().scene().keys[0].cuts[0].release ==
        Approx(openWeight(live.session.scene().scene, "cut1", letGo.frame + 3)).margin(0.002));

  // Esc with unsaved changes asks first: the window stays open.
  live.send("key Escape");
  live.frames(4);
  CHECK_FALSE(live.window->shouldClose());
  live.shot("editor-unsaved-dialog");

  // Ctrl+S writes the scene; it loads, meshes and renders.
  live.send("key ctrl+s");
  live.frames(3);
  CHECK_FALSE(editing.document().modified());
  CHECK(view.title().find(" *") == std::string::npos);
  const Scene saved = loadScene(scene.string());
  CHECK(saved.keys.size() == 2);
  CHECK(saved.keys[1].features.size() == 5);
  CHECK(saved.stiffness.strokes.size() == 1);
  const fs::path frames = scene.parent_path() / "frames";
  const test::CommandRun render = inbetween("render " + scene.string() + " -o " + frames.string());
  INFO(render.err);
  CHECK(render.code == 0);
  CHECK(fs::exists(frames / "frame_0000.png"));

  // A PNG dropped on the window (GLFW's drop callback) becomes a key named after it; undo takes it back.
  fs::copy_file(scene.parent_path() / "arch.png", scene.parent_path() / "arch2.png");
  live.window->dropped({(scene.parent_path() / "arch2.png").string()});
  live.frames(4);
  REQUIRE(editing.keyCount() == 3);
  CHECK(editing.marks().keys[2].name == "arch2");
  CHECK(editing.nextMissing(1));  // its features are asked for
  live.send("key ctrl+z");
  live.frames(3);
  CHECK(editing.keyCount() == 2);
}

TEST_CASE("editor window: the README's chomp made from its two drawings with clicks alone plays, its mouth open at the "
          "open key and the eye carried with the disc", "[window]") {
  // Screenshots for docs/editor.md and the README go to INBETWEEN_SHOTS when it is set.
  const char* shots = std::getenv("INBETWEEN_SHOTS");
  const fs::path folder = fs::temp_directory_path() / "inbetween-editor-chomp";
  fs::remove_all(folder);
  fs::create_directories(folder);
  for (const char* png : {"closed.png", "open.png"})
    fs::copy_file(fs::path(INBETWEEN_SOURCE_DIR) / "tests" / "topology" / "chomp" / png, folder / png);
  const fs::path scene = folder / "scene.json";
  REQUIRE(inbetween("new " + scene.string() + " " + (folder / "closed.png").string() + " " + (folder / "open.png").string() +
                    " --no-window").code == 0);
  editor::EditorSession editing(SceneDocument::load(scene.string()));
  LiveWindow live(scene.string(), kEditWidth, 720, &editing);
  editor::EditorView& view = *live.window->editor();
  const auto shot = [&](const std::string& name) {
    const RgbaImage image = live.shot("editor-chomp-" + name);
    if (shots) writePng((fs::path(shots) / ("editor-" + name + ".png")).string(), image);
  };
  live.send("mousemove --window 600 600");
  live.frames(3);
  shot("new");

  // `top` on both outlines (the second click answers the editor's prompt), renamed from f1.
  live.send(at(view, 0, 128, 26) + " click 1");
  live.frames(3);
  live.send(at(view, 1, 129, 30) + " click 1");
  live.frames(3);
  REQUIRE_FALSE(editing.document().problem());
  // Renamed in the Edit tab, typed: the letters of the tools' shortcuts (q, d, b, c) go into the
  // field, not to the tools.
  renameThroughPanel(live, view, "name", "Rename", "topqdbc");
  CHECK(view.tools().tool == editor::Tool::kFeature);
  REQUIRE(editing.marks().keys[1].features.count("topqdbc"));
  renameThroughPanel(live, view, "name", "Rename", "top");
  REQUIRE(editing.marks().keys[0].features.count("top"));
  REQUIRE(editing.marks().keys[1].features.count("top"));
  // The mouth: a notch from the right edge to the centre in the closed key, then its three
  // features in the open key as the editor asks for them: the lower lip, the upper lip, the tip.
  drawCut(live, view, 0, {229, 128}, {128, 128});
  REQUIRE(editing.marks().keys[0].cuts.size() == 1);
  renameThroughPanel(live, view, "cut 0", "cut 0 rename", "mouth");
  REQUIRE(editing.marks().keys[0].cuts.size() == 1);
  CHECK(editing.marks().keys[0].cuts[0].name == "mouth");
  live.send("key q");
  live.frames(2);
  live.send(at(view, 1, 128, 128) + " mousemove_relative 0 0");  // the prompt is shown in the key's title
  live.frames(3);
  shot("prompt");
  for (const auto& [name, x, y] : {std::tuple<const char*, double, double>{"mouth.left", 211, 186}, {"mouth.right", 211, 70}, {"mouth.tip", 127, 128}}) {
    REQUIRE(editing.nextMissing(0));
    CHECK(editing.nextMissing(0)->feature == name);
    live.send(at(view, 1, x, y) + " click 1");
    live.frames(3);
  }
  INFO((editing.document().problem() ? *editing.document().problem() : std::string()));
  REQUIRE_FALSE(editing.document().problem());
  CHECK(editing.orderProblem().empty());
  // The eye: an interior feature with its disc dragged out, in both keys.
  live.send("key d");
  live.frames(2);
  for (int k = 0; k < 2; ++k) dragInterior(live, view, k, 140, 70, 9);
  renameThroughPanel(live, view, "name", "Rename", "eye");
  REQUIRE(editing.marks().keys[1].interior.count("eye"));
  live.send("key q mousemove --window 600 650");
  REQUIRE(presentUntil(*live.window, [&] { return !live.session.reloader().busy() && !view.awaitingFrame(); }, 120));
  live.frames(10);
  shot("chomp");
  live.send("key ctrl+s");
  live.frames(3);
  CHECK_FALSE(editing.document().modified());

  // The saved scene renders; at the open key (frame 24 of the 2 s loop) the wedge is empty, and
  // at the closed key it is filled.
  const fs::path frames = folder / "frames";
  const test::CommandRun render = inbetween("render " + scene.string() + " -o " + frames.string());
  INFO(render.err);
  REQUIRE(render.code == 0);
  const RgbaImage open = readPng((frames / "frame_0024.png").string()), closed = readPng((frames / "frame_0000.png").string());
  const auto alphaAt = [](const RgbaImage& image, int x, int y) { return image.pixels[4 * (static_cast<size_t>(y) * image.width + x) + 3]; };
  CHECK(alphaAt(open, 190, 128) < 30);    // inside the wedge, between the lips
  CHECK(alphaAt(closed, 190, 128) > 220);
  CHECK(alphaAt(open, 60, 128) > 220);    // the back of the disc
}
