// Static work splits for OpenMP parallel regions: the rows are cut into a fixed number of blocks
// (a thread layout's parts), and a thread takes the same blocks in every loop, so it may read
// what it wrote earlier without a barrier and finds it in its own core's cache. Every block sums
// on its own and the partial sums are added in block order: results are bit-identical from run
// to run and whatever the team (teamFor; thread_budget.h), which OpenMP reductions do not promise.
// The blocks themselves follow the most threads asked for (SolverOptions::threads, or every core),
// so a run with another --threads, or on a machine with another core count, may differ in the
// last bits.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <omp.h>
#include <utility>
#include <vector>

namespace ib {

// Threads for a region over `blocks` blocks: at most the calling thread's OpenMP team size
// (omp_get_max_threads: every core, or what a TeamScope (thread_budget.h) set for the work under
// way). The blocks' results never depend on it: a thread takes blocks self, self + team, ...
inline int teamFor(int blocks) { return std::max(1, std::min(blocks, omp_get_max_threads())); }

// A split of rows among threads fixed by the caller (for example by which vertices each thread's
// part of a Cholesky factor covers): thread p takes rows [start[p], start[p + 1]).
class RowSplit {
 public:
  RowSplit() = default;  // no rows, one thread
  // start: threads + 1 non-decreasing entries, the first 0.
  explicit RowSplit(std::vector<int> start) : start_(std::move(start)) {}
  int threads() const { return start_.size() > 1 ? static_cast<int>(start_.size()) - 1 : 1; }
  int size() const { return start_.empty() ? 0 : start_.back(); }
  int begin(int thread) const { return start_.empty() ? 0 : start_[thread]; }
  int end(int thread) const { return start_.empty() ? 0 : start_[thread + 1]; }

 private:
  std::vector<int> start_;
};

}  // namespace ib
