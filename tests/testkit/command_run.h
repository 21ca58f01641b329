// A shell command run to its end, for the tests of the `inbetween` command itself.
#pragma once

#include <string>

namespace test {

struct CommandRun {
  int code = -1;       // exit code; -1 when the command did not exit normally
  std::string output;  // stdout and stderr together
};

// Runs `command` through the shell with stderr joined to stdout. Throws std::runtime_error when
// no shell could be started.
CommandRun runCommand(const std::string& command);

}  // namespace test
