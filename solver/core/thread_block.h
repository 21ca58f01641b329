// Static work splits for OpenMP parallel regions: each thread takes one contiguous block of rows,
// the same block in every loop, so a thread may read what it wrote earlier without a barrier,
// finds it in its own core's cache, and per-thread partial sums can be added in thread order
// (bit-identical results from run to run, which OpenMP reductions do not promise).
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

// The calling thread's share [first, first + count) of `size` rows, split evenly.
inline std::pair<Eigen::Index, Eigen::Index> rowBlock(Eigen::Index size) {
  const Eigen::Index threads = omp_get_num_threads(), id = omp_get_thread_num();
  const Eigen::Index first = size * id / threads, last = size * (id + 1) / threads;
  return {first, last - first};
}

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
