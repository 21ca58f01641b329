#include "player/key_queue.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <utility>

namespace ib::play {

bool KeyQueue::record(const KeyEvent& event) {
  if (event.key == GLFW_KEY_UNKNOWN) return true;
  if (event.action == GLFW_RELEASE) {
    const bool pressedNow =
        std::find(pressedThisFrame_.begin(), pressedThisFrame_.end(), event.key) != pressedThisFrame_.end();
    if (!pressedNow) return true;
    heldBack_.push_back(event);
    return false;
  }
  if (event.action == GLFW_PRESS) pressedThisFrame_.push_back(event.key);
  if (presses_.size() < kCapacity) presses_.push_back({event.key, (event.mods & GLFW_MOD_CONTROL) != 0, (event.mods & GLFW_MOD_SHIFT) != 0});
  return true;
}

std::vector<KeyPress> KeyQueue::take() { return std::exchange(presses_, {}); }

std::vector<KeyEvent> KeyQueue::nextFrame() {
  pressedThisFrame_.clear();
  return std::exchange(heldBack_, {});
}

}  // namespace ib::play
