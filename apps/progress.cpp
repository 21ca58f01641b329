#include "progress.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace ib::cli {

Progress::Progress() : terminal_(isatty(fileno(stderr)) != 0) {}

Progress::~Progress() { finish(); }

void Progress::update(const std::string& stage, double fraction) {
  if (!terminal_) return;
  const int width = 24;
  const int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * width + 0.5);
  std::fprintf(stderr, "\r[%s%s] %3d%% %-40.40s", std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(),
               static_cast<int>(fraction * 100 + 0.5), stage.c_str());
  std::fflush(stderr);
  shown_ = true;
}

void Progress::finish() {
  if (!shown_) return;
  std::fprintf(stderr, "\r%75s\r", "");
  std::fflush(stderr);
  shown_ = false;
}

}  // namespace ib::cli
