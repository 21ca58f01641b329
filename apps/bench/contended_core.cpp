#include "bench/contended_core.h"

#include "core/error.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace ib {

ContendedCore::ContendedCore() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0 || CPU_COUNT(&allowed) < 2)
    throw InputError("--contended: this process may run on one CPU only, so a busy core would leave nothing to compare");
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &allowed)) cpu_ = c;
  const pid_t parent = getpid();
  child_ = fork();
  if (child_ < 0) throw InputError(std::string("--contended: cannot start the busy process: ") + std::strerror(errno));
  if (child_ == 0) {
    // The child: only async-signal-safe calls until it is killed; it dies with the parent too.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(0);
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu_, &one);
    sched_setaffinity(0, sizeof one, &one);
    volatile unsigned long spin = 0;
    for (;;) spin = spin + 1;
  }
}

ContendedCore::~ContendedCore() {
  if (child_ <= 0) return;
  kill(child_, SIGKILL);
  int status = 0;
  waitpid(child_, &status, 0);
}

}  // namespace ib
