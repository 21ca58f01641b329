// The player's keyboard shortcuts: what each key does to the session and the view, and the list
// the help panel shows. Keys are GLFW key codes.
#pragma once

#include "player/player_ui.h"

#include <vector>

namespace ib::play {

// Applies GLFW key `key`'s shortcut (with Ctrl held or not); false when the key has none.
bool applyShortcut(int key, bool ctrl, PlayerSession& session, UiState& ui);

struct ShortcutHelp {
  const char* keys;  // e.g. "Left / Right"
  const char* does;
};
const std::vector<ShortcutHelp>& shortcutHelp();  // every shortcut, for the help panel

}  // namespace ib::play
