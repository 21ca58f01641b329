#include "core/thread_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <omp.h>
#include <sched.h>
#include <sstream>
#include <string>
#include <unistd.h>

namespace ib {

namespace {

// The numbers of the CPUs this process may run on.
std::vector<int> allowedCpus() {
  std::vector<int> cpus;
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0)
    for (int c = 0; c < CPU_SETSIZE; ++c)
      if (CPU_ISSET(c, &set)) cpus.push_back(c);
#endif
  return cpus;
}

// Runnable tasks right now ("procs_running" in /proc/stat), -1 when unknown.
int runnableTasks() {
  std::ifstream in("/proc/stat");
  std::string word;
  while (in >> word)
    if (word == "procs_running") {
      int count = -1;
      in >> count;
      return count;
    }
  return -1;
}

// This process's threads that are running or runnable now (state R in /proc/self/task/*/stat).
int ownRunnableThreads() {
  int count = 0;
  DIR* tasks = opendir("/proc/self/task");
  if (!tasks) return 1;
  while (const dirent* entry = readdir(tasks)) {
    if (entry->d_name[0] == '.') continue;
    std::ifstream in(std::string("/proc/self/task/") + entry->d_name + "/stat");
    std::string text;
    std::getline(in, text);
    const size_t paren = text.rfind(')');  // the name may hold spaces and parentheses
    if (paren != std::string::npos && paren + 2 < text.size() && text[paren + 2] == 'R') ++count;
  }
  closedir(tasks);
  return std::max(count, 1);
}

}  // namespace

ThreadBudget::ThreadBudget(int limit, bool adapt) : limit_(std::max(1, limit)), threads_(std::max(1, limit)) {
  allowed_ = allowedCpus();
  cpus_ = std::max(1, static_cast<int>(allowed_.size()));
  if (limit_ == 1 || !adapt) return;
  Sample probe;
  measurable_ = !allowed_.empty() && sample(probe);
}

bool ThreadBudget::sample(Sample& out) const {
  std::ifstream in("/proc/stat");
  if (!in) return false;
  const double tick = 1.0 / static_cast<double>(sysconf(_SC_CLK_TCK));
  std::string line;
  double busy = 0;
  int found = 0;
  while (std::getline(in, line)) {
    if (line.compare(0, 3, "cpu") != 0) break;  // the per-CPU lines come first
    if (line.size() < 4 || line[3] < '0' || line[3] > '9') continue;  // the "cpu" total line
    std::istringstream fields(line.substr(3));
    int cpu = -1;
    long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
    fields >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
    if (!fields && !fields.eof()) continue;
    if (!std::binary_search(allowed_.begin(), allowed_.end(), cpu)) continue;
    busy += static_cast<double>(user + nice + system + irq + softirq + steal) * tick;
    ++found;
  }
  if (found == 0) return false;
  double own = 0;
  for (const clockid_t clock : teamClocks_) {
    timespec t{};
    if (clock_gettime(clock, &t) == 0) own += static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
  out.wall = std::chrono::steady_clock::now();
  out.busySeconds = busy;
  out.ownSeconds = own;
  return true;
}

void ThreadBudget::registerTeam() {
  teamClocks_.assign(static_cast<size_t>(limit_), clockid_t{});
  std::vector<char> got(static_cast<size_t>(limit_), 0);
#pragma omp parallel num_threads(limit_)
  {
    const int self = omp_get_thread_num();
    clockid_t clock{};
    if (self < limit_ && pthread_getcpuclockid(pthread_self(), &clock) == 0) {
      teamClocks_[static_cast<size_t>(self)] = clock;
      got[static_cast<size_t>(self)] = 1;
    }
  }
  std::vector<clockid_t> clocks;
  for (size_t i = 0; i < got.size(); ++i)
    if (got[i]) clocks.push_back(teamClocks_[i]);
  teamClocks_ = std::move(clocks);
  master_ = pthread_self();
  registered_ = true;
  haveLast_ = false;
}

int ThreadBudget::decide(double otherCores) const {
  const int taken = static_cast<int>(std::floor(otherCores + 1 - kCoreShare));
  return std::clamp(cpus_ - std::max(0, taken), 1, limit_);
}

int ThreadBudget::snapshotThreads() const {
  const int runnable = runnableTasks();
  if (runnable < 0) return limit_;
  return decide(std::max(0, runnable - ownRunnableThreads()));
}

int ThreadBudget::threads() {
  if (limit_ == 1 || !measurable_) return limit_;
  if (!registered_ || !pthread_equal(master_, pthread_self())) registerTeam();
  const auto now = std::chrono::steady_clock::now();
  if (haveLast_ && std::chrono::duration<double>(now - last_.wall).count() < kWindowSeconds) return threads_;
  Sample current;
  if (!sample(current)) {
    measurable_ = false;
    return threads_ = limit_;
  }
  const double seconds = haveLast_ ? std::chrono::duration<double>(current.wall - last_.wall).count() : 0;
  if (!haveLast_ || seconds > kStaleSeconds) {
    threads_ = snapshotThreads();
  } else {
    const double other = (current.busySeconds - last_.busySeconds) - (current.ownSeconds - last_.ownSeconds);
    otherCores_ = std::max(0.0, other / seconds);
    threads_ = decide(otherCores_);
  }
  last_ = current;
  haveLast_ = true;
  return threads_;
}

TeamScope::TeamScope(ThreadBudget& budget) : budget_(budget), previous_(omp_get_max_threads()) { update(); }

TeamScope::~TeamScope() { omp_set_num_threads(previous_); }

void TeamScope::update() { omp_set_num_threads(std::min(budget_.threads(), previous_)); }

int TeamScope::threads() const { return omp_get_max_threads(); }

ThreadLimit::ThreadLimit(int threads) : previous_(omp_get_max_threads()) {
  if (threads > 0) omp_set_num_threads(threads);
}

ThreadLimit::~ThreadLimit() { omp_set_num_threads(previous_); }

}  // namespace ib
