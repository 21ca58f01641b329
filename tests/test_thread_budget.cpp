// The thread policy (solver/core/thread_budget.h): a budget stays within its limit, comes down to
// one thread while another process keeps a core busy, and the solver's results do not depend on
// how many threads run its blocks.
#include "bench/contended_core.h"
#include "core/thread_budget.h"
#include "interpolation/interpolator.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <sched.h>
#include <thread>

using namespace ib;

namespace {

// How many CPUs this process may run on.
int allowedCpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  return sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 1;
}

}  // namespace

TEST_CASE("thread budget: a budget gives between one thread and its limit, and a limit of one or a fixed budget its limit") {
  ThreadBudget one(1), fixed(3, false), adaptive(2);
  for (int k = 0; k < 5; ++k) {
    CHECK(one.threads() == 1);
    CHECK(fixed.threads() == 3);
    const int threads = adaptive.threads();
    CHECK(threads >= 1);
    CHECK(threads <= 2);
    std::this_thread::sleep_for(std::chrono::milliseconds(60));  // over some windows
  }
}

TEST_CASE("thread budget: with another process spinning on one allowed CPU, a budget of all of them comes down to fewer") {
  const int cpus = allowedCpus();
  if (cpus < 2) return;  // one CPU: nothing to take away
  const ContendedCore busy;  // the benchmarks' busy core: a process pinned to the last allowed CPU
  ThreadBudget budget(cpus);
  // Windows of 100 ms: the busy CPU shows within a few (the first answer is a snapshot).
  bool fewer = false;
  for (int k = 0; k < 100 && !fewer; ++k) {
    fewer = budget.threads() < cpus;
    if (!fewer) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  INFO("other work measured: " << budget.otherCores() << " cores");
  CHECK(fewer);
}

TEST_CASE("thread budget: a two-block solve gives the same bits on one thread as on two") {
  // 10k vertices: the layout has two blocks whatever runs them. adaptThreads off and the calling
  // thread's team size set: exactly one thread, then exactly two.
  const auto f = test::strip(10000, 2);
  SolverOptions options;
  options.threads = 2;
  options.adaptThreads = false;
  const Eigen::Vector2d w(0.35, 0.65);
  const auto solveOn = [&](int threads) {
    const ThreadLimit limit(threads);
    Interpolator solver(f.mesh, {}, options);
    InterpolationResult result = solver.solve(w);
    REQUIRE(solver.threads() == 2);
    CHECK(result.threads == threads);
    result = solver.solve(Eigen::Vector2d(0.5, 0.5), &result.x);  // a warm frame too
    CHECK(result.threads == threads);
    return result;
  };
  const InterpolationResult one = solveOn(1), two = solveOn(2);
  CHECK(one.iterations == two.iterations);
  CHECK(one.energy == two.energy);
  CHECK((one.x - two.x).cwiseAbs().maxCoeff() == 0);
}
