// A shell command run to its end, for the tests of the `inbetween` command itself.
#pragma once

#include <string>
#include <vector>

namespace test {

struct CommandRun {
  int code = -1;       // exit code; -1 when the command did not exit normally
  std::string output;  // stdout and stderr together, in the order they arrived
  std::string out;     // stdout alone
  std::string err;     // stderr alone
};

// Runs `command` through the shell (/bin/sh -c), reading its stdout and stderr apart and
// together. Throws std::runtime_error when no shell could be started.
CommandRun runCommand(const std::string& command);

// `words` as one shell command line, each word quoted: paths and messages pass unchanged.
std::string commandLine(const std::vector<std::string>& words);

}  // namespace test
