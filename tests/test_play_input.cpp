// The player's window under Xvfb with real X input (xdotool) as a quick user gives it: a click
// that does not move, key taps shorter than a frame. In this process (LiveWindow) the input is
// sent between two frames, the moment such a click or tap lands, and the state it changes (the
// view's pan, the transport's frame) is read from the window's own session and UI; the running
// `inbetween play` is driven the same way and read through its F12 screenshots. Screenshots are
// written to the temporary folder, to look at.
#include "core/atomic_file.h"
#include "play_fixtures.h"
#include "player/key_queue.h"
#include "player/player_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

using namespace ib;
using namespace playtest;
namespace fs = std::filesystem;

TEST_CASE("play: a click in the picture after the pointer moved far leaves the view where it was, and a drag pans it "
          "by the pointer's motion", "[.window]") {
  LiveWindow live(kScene);
  const play::PixelRect canvas = play::canvasRect(kWidth, kHeight);
  // Inside the drawing, below and right of the readouts panel at the picture's top left.
  const int cx = static_cast<int>(0.5 * (canvas.x0 + canvas.x1)) + 60, cy = static_cast<int>(0.5 * (canvas.y0 + canvas.y1)) + 40;
  // The pointer far from where it will click (over the side panel, 500 px right), seen there by a
  // frame; then, between two frames, it jumps into the picture and clicks.
  live.send("mousemove --window " + std::to_string(kWidth - 40) + " " + std::to_string(cy - 150));
  live.frames(5);
  const RgbaImage before = live.shot("click-before");
  live.send("mousemove --window " + std::to_string(cx) + " " + std::to_string(cy) + " click 1");
  live.frames(5);
  const RgbaImage after = live.shot("click-after");
  const play::UiState& ui = live.window->ui();
  CHECK(ui.navigation.pan().x() == 0);
  CHECK(ui.navigation.pan().y() == 0);
  CHECK(pictureDifference(before, after) == 0);

  // A drag: the button goes down, the pointer moves 60 px right and 40 px up while held (over
  // several frames), the button comes up. The picture follows the pointer.
  const Eigen::Vector2d clicked = ui.navigation.pan();
  live.send("mousedown 1");
  live.frames(3);
  live.send("mousemove --window " + std::to_string(cx + 30) + " " + std::to_string(cy - 20));
  live.frames(3);
  live.send("mousemove --window " + std::to_string(cx + 60) + " " + std::to_string(cy - 40));
  live.frames(3);
  live.send("mouseup 1");
  live.frames(3);
  const RgbaImage dragged = live.shot("click-dragged");
  const render::ViewBox view = ui.navigation.windowView({0, 0, 128, 128}, canvas, kWidth, kHeight);
  const double unitsPerPixel = (view.x1 - view.x0) / kWidth;  // drawing pixels per window pixel
  CHECK(ui.navigation.pan().x() - clicked.x() == Approx(-60 * unitsPerPixel));
  CHECK(ui.navigation.pan().y() - clicked.y() == Approx(40 * unitsPerPixel));
  CHECK(pictureDifference(before, dragged) > 500);
}

TEST_CASE("play: N quick taps of an arrow key between two frames step the transport by exactly N frames", "[.window]") {
  LiveWindow live(kScene);
  play::Transport& transport = live.session.transport();
  REQUIRE(transport.frame() == 0);
  REQUIRE_FALSE(transport.playing());
  // Press and release 2 ms apart, five times over, all before the next frame polls. (Not 0 ms:
  // GLFW drops a second press of a key stamped with the same X time, in milliseconds, as the one
  // before, taking it for an input method's duplicate; no hand taps that fast.)
  live.send("key --delay 4 Right Right Right Right Right");
  live.frames(3);
  CHECK(transport.frame() == 5);
  live.send("key --delay 4 Left Left");
  live.frames(3);
  CHECK(transport.frame() == 3);
  // Taps while frames are presented, 7 of them 10 ms apart: some land within a frame, some across.
  live.sendWhilePresenting("key --delay 10 Right Right Right Right Right Right Right");
  CHECK(transport.frame() == 10);
  live.shot("taps-frame-10");  // the transport's readout says "frame 10 / ..."
  // Space, tapped: plays; tapped again: pauses.
  live.send("key --delay 0 space");
  live.frames(3);
  CHECK(transport.playing());
  live.send("key --delay 0 space");
  live.frames(3);
  CHECK_FALSE(transport.playing());
}

TEST_CASE("play: a quick Ctrl+S saves the parameters, and keys typed into a value field are not shortcuts", "[.window]") {
  const fs::path dir = sceneCopy("quick-keys");
  const std::string file = (dir / "scene.json").string();
  LiveWindow live(file);
  live.session.parameters().set("tau", 0.004);
  live.frames(2);
  live.send("key --delay 0 ctrl+s");
  live.frames(3);
  CHECK(readFile(file).find("\"tau\": 0.004") != std::string::npos);

  // Ctrl+click on tau's slider (the Parameters tab's second row) opens the field that takes a
  // typed value; "1" there is text, not the wireframe's shortcut, and Enter sets the value. (Not
  // a double-click: ImGui takes one mouse event per frame, and at lavapipe's frame times under
  // a loaded CI the second click can land past the 0.3 s a double-click allows.)
  live.sendWhilePresenting("mousemove --window 730 102 keydown ctrl click 1 keyup ctrl");
  live.send("type --delay 0 1");
  live.frames(3);
  live.send("key --delay 0 Return");
  live.frames(3);
  CHECK_FALSE(live.window->ui().view.overlays.wireframe);
  CHECK(live.session.parameters().get("tau") == 1);
  live.send("key --delay 0 1");  // now a shortcut again
  live.frames(3);
  CHECK(live.window->ui().view.overlays.wireframe);
}

TEST_CASE("play: the key queue keeps presses and repeats in order with Ctrl, holds at most its capacity, and holds "
          "back the release of a key pressed within the frame", "[.window]") {
  play::KeyQueue queue;
  CHECK(queue.record({GLFW_KEY_RIGHT, 114, GLFW_PRESS, 0}));
  CHECK_FALSE(queue.record({GLFW_KEY_RIGHT, 114, GLFW_RELEASE, 0}));  // pressed this frame: held back
  CHECK(queue.record({GLFW_KEY_S, 39, GLFW_PRESS, GLFW_MOD_CONTROL}));
  CHECK(queue.record({GLFW_KEY_LEFT, 113, GLFW_REPEAT, GLFW_MOD_SHIFT}));
  CHECK(queue.record({GLFW_KEY_LEFT, 113, GLFW_RELEASE, 0}));  // pressed in a frame before: passed on
  const std::vector<play::KeyPress> presses = queue.take();
  REQUIRE(presses.size() == 3);
  CHECK((presses[0].key == GLFW_KEY_RIGHT && !presses[0].ctrl));
  CHECK((presses[1].key == GLFW_KEY_S && presses[1].ctrl));
  CHECK((presses[2].key == GLFW_KEY_LEFT && !presses[2].ctrl));
  CHECK(queue.take().empty());
  const std::vector<play::KeyEvent> held = queue.nextFrame();
  REQUIRE(held.size() == 1);
  CHECK((held[0].key == GLFW_KEY_RIGHT && held[0].scancode == 114 && held[0].action == GLFW_RELEASE));
  CHECK(queue.nextFrame().empty());
  CHECK(queue.record({GLFW_KEY_S, 39, GLFW_RELEASE, 0}));  // its press was a frame ago
  for (size_t i = 0; i < play::KeyQueue::kCapacity + 10; ++i) queue.record({GLFW_KEY_RIGHT, 114, GLFW_PRESS, 0});
  CHECK(queue.take().size() == play::KeyQueue::kCapacity);
}

namespace {

// The transport bar's readout ("frame 5 / 47   0.208 s") in a kWidth x kHeight screenshot.
int readoutDifference(const RgbaImage& a, const RgbaImage& b) {
  int differ = 0;
  for (int y = kHeight - 38; y < kHeight - 8; ++y)
    for (int x = 400; x < kWidth - static_cast<int>(play::kSidePanelWidth); ++x)
      for (int c = 0; c < 3; ++c)
        if (a.at(x, y)[c] != b.at(x, y)[c]) {
          ++differ;
          break;
        }
  return differ;
}

}  // namespace

TEST_CASE("play: in the running `inbetween play`, a click in the picture moves nothing, and five quick taps of Right "
          "and one of F12 show frame 5 as a scripted run does", "[.window]") {
  const RgbaImage frame4 = screenshot("readout-4", "", 5), frame5 = screenshot("readout-5", "", 6);
  REQUIRE(readoutDifference(frame4, frame5) > 50);  // the readout tells the frames apart
  const fs::path dir = fs::temp_directory_path() / "inbetween-play-test-e2e-input";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto shotFile = [&](int n) { return (dir / ("inbetween-000" + std::to_string(n) + ".png")).string(); };
  test::CommandRun run;
  std::atomic<bool> ended{false};
  std::thread player([&] {  // F12 writes inbetween-NNNN.png into the folder the player runs in
    run = inbetween("play " + kScene + " --size 960x600 --device cpu --validation", "cd " + dir.string() + " &&");
    ended = true;
  });
  // The input, as a user gives it; false at the first screenshot that does not come. No REQUIRE
  // here: the player is closed below whatever happens.
  const auto drive = [&] {
    std::string window;
    for (int k = 0; k < 300 && window.empty(); ++k) {
      window = xdotool("search --name \"inbetween play - " + kScene + "\" | head -n 1");
      if (window.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    if (window.empty()) return false;
    xdotool("windowfocus --sync " + window);
    // The window takes input once its first frames are drawn, which nothing announces: F12 until
    // a screenshot comes. From then on one tap of each, no retries.
    if (!actUntil([] { xdotool("key F12"); }, [&] { return fs::exists(shotFile(1)); }, 10)) return false;
    const auto tapF12 = [&](int n) {
      xdotool("sleep 0.5 key --delay 0 F12");
      return actUntil([] {}, [&] { return fs::exists(shotFile(n)) && fs::file_size(shotFile(n)) > 0; }, 1);
    };
    if (!tapF12(2)) return false;  // frame 0, solved by now
    xdotool("mousemove --window " + window + " 920 94 sleep 0.5 mousemove --window " + window + " 370 284 click 1");
    if (!tapF12(3)) return false;
    xdotool("key --delay 4 Right Right Right Right Right");
    return tapF12(4);
  };
  const bool driven = drive();
  xdotool("key Escape");
  const bool closed = actUntil([] {}, [&] { return ended.load(); }, 6);
  if (!closed) test::runCommand("pkill -f \"inbetween play " + kScene + " --size 960x600\"");  // so that the test ends
  player.join();
  REQUIRE(driven);
  CHECK(closed);
  INFO(run.output);
  CHECK(run.code == 0);
  const RgbaImage clickBefore = readPng(shotFile(2)), clickAfter = readPng(shotFile(3)), tapped = readPng(shotFile(4));
  CHECK(pictureDifference(clickBefore, clickAfter) == 0);
  CHECK(readoutDifference(tapped, frame5) == 0);
  CHECK(pictureDifference(tapped, frame5) < 20);  // frame 5, where a scripted run draws it: not panned
}
