#include "testkit/command_run.h"

#include <cerrno>
#include <fcntl.h>
#include <poll.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace test {

namespace {

// Closes both ends of every pipe that is still open.
void closeAll(int (&pipes)[2][2]) {
  for (auto& p : pipes)
    for (int& fd : p)
      if (fd >= 0) {
        close(fd);
        fd = -1;
      }
}

}  // namespace

CommandRun runCommand(const std::string& command) {
  int pipes[2][2] = {{-1, -1}, {-1, -1}};  // [stdout, stderr][read end, write end]
  for (auto& p : pipes)
    if (pipe2(p, O_CLOEXEC) != 0) {
      closeAll(pipes);
      throw std::runtime_error("cannot make a pipe for: " + command);
    }
  const pid_t child = fork();
  if (child < 0) {
    closeAll(pipes);
    throw std::runtime_error("cannot start a shell for: " + command);
  }
  if (child == 0) {  // dup2 clears close-on-exec on the copies
    dup2(pipes[0][1], STDOUT_FILENO);
    dup2(pipes[1][1], STDERR_FILENO);
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(pipes[0][1]);
  close(pipes[1][1]);
  pipes[0][1] = pipes[1][1] = -1;

  // Both streams read as they come, so neither pipe fills up while the other is waited on.
  CommandRun run;
  std::string* streams[2] = {&run.out, &run.err};
  pollfd fds[2] = {{pipes[0][0], POLLIN, 0}, {pipes[1][0], POLLIN, 0}};
  int open = 2;
  char buffer[4096];
  while (open > 0) {
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || fds[i].revents == 0) continue;
      const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {  // end of the stream (or an error on it)
        fds[i].fd = -1;
        --open;
        continue;
      }
      streams[i]->append(buffer, static_cast<size_t>(n));
      run.output.append(buffer, static_cast<size_t>(n));
    }
  }
  closeAll(pipes);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string commandLine(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) {
    if (!line.empty()) line += ' ';
    line += '\'';
    for (char c : word) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

}  // namespace test
