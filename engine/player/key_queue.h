// The player's key events between two frames, from GLFW's key callback. Dear ImGui 1.86 samples
// which keys are down once per frame, so a key pressed and released between two frames (a quick
// tap, or xdotool's `key`) never shows as down there. Here every press is queued for the
// shortcuts, in order; and the release of a key pressed since the last frame is held back for the
// next one, so that ImGui's own widgets (Enter in a text field) see the key down for a frame.
#pragma once

#include <cstddef>
#include <vector>

namespace ib::play {

struct KeyPress {
  int key = 0;        // GLFW key code
  bool ctrl = false;  // Ctrl was held when it went down
  bool shift = false; // Shift was held when it went down
};

// One GLFW key event, as the key callback gets it.
struct KeyEvent {
  int key = 0, scancode = 0, action = 0, mods = 0;
};

class KeyQueue {
 public:
  // More presses than this between two frames (the window stalled) are dropped, the oldest kept:
  // a stall does not turn into a burst of frame steps.
  static constexpr size_t kCapacity = 64;

  // Queues a press or the system's key repeat for the shortcuts. Returns whether to pass the event
  // on to ImGui now: false for the release of a key pressed since the last frame, held back.
  bool record(const KeyEvent& event);
  // Every press queued since the last take(), oldest first; the queue is left empty.
  std::vector<KeyPress> take();
  // Starts a frame: the releases held back, to pass on to ImGui before the frame's own events.
  std::vector<KeyEvent> nextFrame();

 private:
  std::vector<KeyPress> presses_;
  std::vector<int> pressedThisFrame_;  // keys pressed since nextFrame()
  std::vector<KeyEvent> heldBack_;     // their releases, in order
};

}  // namespace ib::play
