#include "testkit/command_run.h"

#include <cstdio>
#include <stdexcept>
#include <sys/wait.h>

namespace test {

CommandRun runCommand(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot start a shell for: " + command);
  CommandRun run;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) run.output += buffer;
  const int status = pclose(pipe);
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace test
