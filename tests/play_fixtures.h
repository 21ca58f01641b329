// What the player's window tests share (test_play.cpp, test_play_controls.cpp, test_play_input.cpp):
// scripted runs of `inbetween play` and their screenshots compared with drawings and rendered
// frames through the player's own layout, scene copies to edit, real input through xdotool, and
// a player window in the test's process to send it to (LiveWindow).
#pragma once

#include "core/png_image.h"
#include "player/player_session.h"
#include "player/player_window.h"
#include "testkit/command_run.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace ib::editor {
class EditorSession;
class EditorView;
}  // namespace ib::editor

namespace playtest {

constexpr int kWidth = 960, kHeight = 600;  // the scripted window's size
extern const std::string kScene;            // square-arch-notch's scene file

// Runs `inbetween ARGS` (prefix: words before the command, e.g. env -u DISPLAY).
test::CommandRun inbetween(const std::string& args, const std::string& prefix = "");

// A scripted run of `frames` frames of a scene (default square-arch-notch) in a kWidth x kHeight
// window on lavapipe with the validation layer; returns its screenshot (the test fails when the
// run does).
ib::RgbaImage screenshot(const std::string& name, const std::string& options, int frames = 1, const std::string& scene = kScene);

// square-arch-notch's drawing `name` ("square.png").
ib::RgbaImage drawing(const std::string& name);

// Compares the screenshot with `art` (a key's drawing or a rendered frame, on the scene's
// 128 x 128 canvas) at every pixel of art whose 7 x 7 neighbourhood is one colour (shape interiors
// and the paper away from outlines, which move by a fraction of a pixel between a key and the
// solve at its weights), mapped through the player's layout. Returns how many of those samples
// are off by more than `tolerance` /255 in a channel; opaque texels are compared to their colour,
// transparent ones to the backdrop's grey; the readouts' and banner's places are skipped.
int mismatches(const ib::RgbaImage& shot, const ib::RgbaImage& art, int tolerance, int* compared);

// Compares every pixel of the screenshot's picture (the canvas outside the readouts and banner)
// with `art` (a key's drawing on the scene's 128 x 128 canvas) as the player's view maps it, edges
// included: the drawing sampled at the pixel's centre (nearest texel, or bilinear in premultiplied
// alpha), over the backdrop as presented (the commonest colour where the drawing has nothing). Under nearest sampling, pixels whose centre falls within 0.02
// texel of a texel's side (either texel is right) are skipped. Returns how many are off by more
// than `tolerance` /255 in a channel.
int drawnMismatches(const ib::RgbaImage& shot, const ib::RgbaImage& art, bool nearest, int tolerance, int* compared);

// Pixels of the picture (the canvas outside the readouts) that differ by more than 32/255.
int pictureDifference(const ib::RgbaImage& a, const ib::RgbaImage& b);

// A copy of the square-arch-notch scene in its own temporary folder, to edit.
std::filesystem::path sceneCopy(const std::string& name);

// Presents frames until `done` holds (true) or `seconds` pass (false).
bool presentUntil(ib::play::PlayerWindow& window, const std::function<bool()>& done, double seconds);

// Whether the session's messages hold an error (error = true) or a notice.
bool hasMessage(ib::play::PlayerSession& session, bool error);

// `xdotool ARGS` against the X display the test runs on; its output without the final newline.
std::string xdotool(const std::string& args);

// Repeats `act` until `done` holds (true), at most `attempts` times, `done` polled for up to 5 s
// after each: a window takes input once its first frames are drawn, which nothing announces.
bool actUntil(const std::function<void()>& act, const std::function<bool()>& done, int attempts);

// A player window in this process on `scene` (kWidth x kHeight unless said), on lavapipe with the
// validation layer (silent, checked at the end), paused on frame 0 once it is solved and drawn,
// with the keyboard's focus (no window manager runs under Xvfb: xdotool gives it). Real X input
// sent to it by send() lands between two frames; the test reads what it changed from the session
// and the UI.
struct LiveWindow {
  ib::play::PlayerSession session;
  std::unique_ptr<ib::play::PlayerWindow> window;
  std::string id;  // the X window, for xdotool

  // With `editor`, the editor's window (`inbetween edit`) over that session's document.
  explicit LiveWindow(const std::string& scene, int width = kWidth, int height = kHeight,
                      ib::editor::EditorSession* editor = nullptr);
  ~LiveWindow();

  // `count` frames, 20 ms apart: the X events sent before are taken in the first.
  void frames(int count);
  // The window as presented, UI included, also written to inbetween-play-test-NAME.png.
  ib::RgbaImage shot(const std::string& name);
  // `xdotool ARGS`, the window's id after every "--window", run to its end between two frames.
  void send(const std::string& args);
  // The same with frames presented meanwhile (a double-click needs a frame for each click), then
  // 3 more.
  void sendWhilePresenting(const std::string& args);

 private:
  std::string withId(std::string args) const;
};

// "mousemove --window X Y" at the editor's key k's drawing point (x, y), offset by (dx, dy) window pixels.
std::string at(ib::editor::EditorView& view, int key, double x, double y, int dx = 0, int dy = 0);

// Clicks the Edit tab's control `name` (EditorView::buttonCentre) with the real pointer: moved
// there, a few frames hovering, then pressed and released, as a hand does.
void clickControl(LiveWindow& live, ib::editor::EditorView& view, const std::string& name);

}  // namespace playtest
