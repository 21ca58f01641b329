#include "player/shortcuts.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

namespace ib::play {

bool applyShortcut(int key, bool ctrl, PlayerSession& session, UiState& ui) {
  Transport& transport = session.transport();
  render::Overlays& overlays = ui.view.overlays;
  if (ctrl) {
    if (key != GLFW_KEY_S) return false;
    session.saveParameters();
    return true;
  }
  switch (key) {
    case GLFW_KEY_SPACE: transport.toggle(); break;
    case GLFW_KEY_LEFT: transport.step(-1); break;
    case GLFW_KEY_RIGHT: transport.step(1); break;
    case GLFW_KEY_DOWN: transport.step(-10); break;
    case GLFW_KEY_UP: transport.step(10); break;
    case GLFW_KEY_HOME: transport.toStart(); break;
    case GLFW_KEY_END: transport.toEnd(); break;
    case GLFW_KEY_L: transport.setLoop(!transport.loop()); break;
    case GLFW_KEY_P: transport.setPingPong(!transport.pingPong()); break;
    case GLFW_KEY_I: transport.setRange(transport.frame(), std::max(transport.frame(), transport.out())); break;
    case GLFW_KEY_O: transport.setRange(std::min(transport.frame(), transport.in()), transport.frame()); break;
    case GLFW_KEY_LEFT_BRACKET: transport.setSpeed(transport.speed() / 1.25); break;
    case GLFW_KEY_RIGHT_BRACKET: transport.setSpeed(transport.speed() * 1.25); break;
    case GLFW_KEY_W: session.setWeightsMode(!session.weightsMode()); break;
    case GLFW_KEY_F: ui.navigation.fit(); break;
    case GLFW_KEY_1: overlays.wireframe = !overlays.wireframe; break;
    case GLFW_KEY_2: overlays.cohesive = !overlays.cohesive; break;
    case GLFW_KEY_3: overlays.features = !overlays.features; break;
    case GLFW_KEY_F12: ui.screenshotRequested = true; break;
    case GLFW_KEY_ESCAPE: ui.closeRequested = true; break;
    default: return false;
  }
  return true;
}

const std::vector<ShortcutHelp>& shortcutHelp() {
  static const std::vector<ShortcutHelp> help = {
      {"Space", "play / pause"},
      {"Left / Right", "one frame back / forward"},
      {"Down / Up", "ten frames back / forward"},
      {"Home / End", "to the in / out point"},
      {"L", "loop on / off"},
      {"P", "ping-pong on / off"},
      {"I / O", "in / out point at the current frame"},
      {"[ / ]", "slower / faster"},
      {"W", "weights mode on / off"},
      {"F", "fit the drawing to the window"},
      {"wheel / drag", "zoom at the pointer / pan"},
      {"1 / 2 / 3", "wireframe / cohesive edges / features"},
      {"Ctrl+S", "save parameters into the scene"},
      {"F12", "screenshot (PNG, UI included)"},
      {"Esc", "close the player"},
      {"drop a file", "open that scene.json"},
      {"edit: Q / C / D / B", "tool: features / cut / interior / stiffness"},
      {"edit: click, drag", "place a feature on the outline, move it along"},
      {"edit: Enter / Esc", "end / cancel the cut being drawn"},
      {"edit: Delete", "remove the selected feature (Shift: in every key)"},
      {"edit: right drag / wheel", "pan / zoom the key under the pointer"},
      {"edit: Ctrl+Z / Ctrl+Shift+Z", "undo / redo"},
      {"edit: Ctrl+S", "save the scene"},
      {"edit: drop PNGs", "add them as keys"},
  };
  return help;
}

}  // namespace ib::play
