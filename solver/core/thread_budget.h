// How many threads the solver's parallel work should use now: the thread policy, in one place
// (docs/solver.md, "Threads on a busy machine").
//
// Work is split into a fixed number of blocks (thread_block.h: a thread layout's parts), so its
// results do not depend on how many threads run them; a budget decides, stretch by stretch, how
// many threads that is. Two threads that meet at barriers many times per millisecond lose badly
// when another program keeps a core busy: one of them is descheduled for a time slice while the
// other waits (2 cores, one kept busy: a 16k-vertex solve 2x slower on two threads than on one,
// and 10-60x on some scenes with two such programs). So the budget measures what the machine's
// other work takes of the cores this process may run on, and runs the work on the cores that are
// left: every block on one thread when another program needs a core, all of them in parallel
// when the cores are free.
//
// The measure: over windows of at least kWindowSeconds, the busy time of the allowed CPUs (Linux
// /proc/stat: user, nice, system, irq, softirq and steal) minus the CPU time of the threads that
// ran this budget's work (the calling thread and its OpenMP team), in cores. A window is closed
// only when threads() is called; a stretch longer than kStaleSeconds without a call starts over
// from a snapshot of the runnable tasks. Where /proc/stat cannot be read, the budget is its limit.
#pragma once

#include <chrono>
#include <ctime>
#include <pthread.h>
#include <vector>

namespace ib {

class ThreadBudget {
 public:
  // limit: the most threads the work can use (its blocks), >= 1. A limit of 1 never measures;
  // nor does adapt = false, which always gives the limit (to compare fixed thread counts).
  explicit ThreadBudget(int limit, bool adapt = true);

  int limit() const { return limit_; }
  // The threads to use for the next stretch of work, in [1, limit()]. Cheap between windows (a
  // clock read); call it from the thread that runs the work (the OpenMP team's master).
  int threads();
  // What the last window measured: the other work on the allowed CPUs, in cores (0 before the
  // first window or without /proc/stat).
  double otherCores() const { return otherCores_; }

  // s: the shortest window measured; the longest gap after which a window starts over.
  static constexpr double kWindowSeconds = 0.1;
  static constexpr double kStaleSeconds = 1.0;
  // cores: other work at or above this share of a core takes one thread from the budget (rounded
  // to the nearest core: 0.5 of a core busy elsewhere gives 1 thread on a 2-core machine).
  static constexpr double kCoreShare = 0.5;

 private:
  struct Sample {
    std::chrono::steady_clock::time_point wall;
    double busySeconds = 0;  // the allowed CPUs' busy time since boot
    double ownSeconds = 0;   // the team threads' CPU time
  };
  bool sample(Sample& out) const;  // false without /proc/stat
  void registerTeam();             // the team's CPU clocks, from the calling thread
  int decide(double otherCores) const;
  int snapshotThreads() const;     // from the tasks runnable right now

  int limit_ = 1;
  int cpus_ = 1;                   // CPUs in this process's affinity mask
  std::vector<int> allowed_;       // their numbers
  bool measurable_ = false;
  pthread_t master_{};             // the thread the team clocks were taken from
  bool registered_ = false;
  std::vector<clockid_t> teamClocks_;
  Sample last_;
  bool haveLast_ = false;
  int threads_ = 1;
  double otherCores_ = 0;
};

// Sets the calling thread's OpenMP team size (omp_set_num_threads, which teamFor in
// thread_block.h reads) from a budget for the regions of one stretch of work, e.g. a solve, and
// restores the previous size when it goes out of scope. update() asks the budget again (e.g.
// once per iteration). The size the calling thread had (every core, or a ThreadLimit's, or
// OMP_NUM_THREADS) caps it.
class TeamScope {
 public:
  explicit TeamScope(ThreadBudget& budget);
  ~TeamScope();
  TeamScope(const TeamScope&) = delete;
  TeamScope& operator=(const TeamScope&) = delete;
  void update();
  int threads() const;  // the team size set last

 private:
  ThreadBudget& budget_;
  int previous_;
};

// The most threads for the work of a scope on the calling thread (omp_set_num_threads), for an
// option such as `--threads N`: budgets made inside take it as their limit. 0 leaves every core.
// Restores the previous count when it goes out of scope.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  int previous_;
};

}  // namespace ib
