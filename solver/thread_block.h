// Static work split for OpenMP parallel regions: each thread takes one contiguous block of rows,
// the same block in every loop of the region, so a thread may read what it wrote earlier without a
// barrier, and per-thread partial sums can be added in thread order (bit-identical results from
// run to run, which OpenMP reductions do not promise).
#pragma once

#include <Eigen/Core>
#include <omp.h>
#include <utility>

namespace ib {

// The calling thread's share [first, first + count) of `size` rows.
inline std::pair<Eigen::Index, Eigen::Index> rowBlock(Eigen::Index size) {
  const Eigen::Index threads = omp_get_num_threads(), id = omp_get_thread_num();
  const Eigen::Index first = size * id / threads, last = size * (id + 1) / threads;
  return {first, last - first};
}

}  // namespace ib
