// Progress on a terminal: one line on stderr, rewritten in place; silent when stderr is not a tty.
#pragma once

#include <string>

namespace ib::cli {

class Progress {
 public:
  Progress();
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // stage: what is being done; fraction: of the whole command, in [0, 1].
  void update(const std::string& stage, double fraction);
  void finish();  // clears the line

 private:
  bool terminal_ = false;
  bool shown_ = false;
};

}  // namespace ib::cli
