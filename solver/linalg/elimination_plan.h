// How the sparse Cholesky solves split among threads: the elimination tree of H's factor is cut
// below its top separator into independent subtrees, which threads solve side by side, and an
// elimination order can put each thread's subtrees in one contiguous range (EliminationPlan).
#pragma once

#include <Eigen/Sparse>
#include <vector>

namespace ib {

// Independent subtrees of an elimination tree, one list of columns per thread, and the top
// separator above them, which is solved serially.
struct EliminationSchedule {
  std::vector<std::vector<int>> part;  // columns ascending: children before parents
  std::vector<int> top;                // ascending as well
};

// parent: the elimination tree (n entries, -1 at a root, a parent after its children); entries:
// the factor's nonzeros in each column, which weigh the subtrees so the threads' shares balance.
EliminationSchedule scheduleSubtrees(const std::vector<int>& parent, const std::vector<long>& entries, int threads);

// An elimination order in which each thread's independent subtrees are contiguous. A caller that
// numbers its unknowns in this order gets solves without permutations, and each thread's share
// of the unknowns is one range of rows, which it can keep in all its other loops too.
struct EliminationPlan {
  std::vector<int> order;      // order[k]: the unknown eliminated k-th (a permutation of 0..n-1)
  std::vector<int> partStart;  // threads + 1 entries: thread p's subtrees are positions
                               // [partStart[p], partStart[p + 1]) of the order; the top
                               // separator, solved serially, is [partStart.back(), n)
};

// METIS nested dissection of H's pattern (n x n, symmetric positive definite, lower triangle
// read; only the pattern matters), split among `threads` as the solves split it.
EliminationPlan planElimination(const Eigen::SparseMatrix<double>& H, int threads);

}  // namespace ib
