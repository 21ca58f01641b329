// A busy core for the benchmarks' --contended cases: another process, pinned to one of this
// process's CPUs, that spins for as long as the object lives, as a paint program, a browser or a
// video call would keep a core busy beside the animator's work.
#pragma once

#include <sys/types.h>

namespace ib {

class ContendedCore {
 public:
  // Starts the busy process on the last CPU this process may run on. InputError when it cannot
  // be started or this process may run on one CPU only (nothing would be left to compare).
  ContendedCore();
  ~ContendedCore();  // kills and reaps it
  ContendedCore(const ContendedCore&) = delete;
  ContendedCore& operator=(const ContendedCore&) = delete;

  int cpu() const { return cpu_; }  // the CPU it keeps busy

 private:
  pid_t child_ = -1;
  int cpu_ = -1;
};

}  // namespace ib
