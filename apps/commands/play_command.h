// `inbetween play SCENE [...]`: the interactive player (a window with the animation and the
// sliders), or, with --frames and --screenshot, a scripted run that writes the window as PNG.
#pragma once

#include <string>
#include <vector>

namespace ib {

int runPlay(const std::vector<std::string>& args);
// The player's window over SCENE with play's options (after `--help` was handled); `edit` adds
// the editor (`inbetween edit SCENE`).
int runPlayerWindow(const std::vector<std::string>& args, bool edit);

}  // namespace ib
