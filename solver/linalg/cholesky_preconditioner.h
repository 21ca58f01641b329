// Sparse Cholesky factor H = L L^T (n x n, shared by the x and y columns) used by the global
// step. The symbolic analysis (METIS nested-dissection ordering, elimination tree split) is
// done on the first factorize() and reused: later calls must keep the sparsity pattern.
//
// The solver only ever uses H as a fixed quadratic model of the energy (x <- x - H^{-1} g), so
// the factor is stored in single precision for the solves; every residual and energy stays in
// double. Solves for both columns run fused; the two halves of the elimination tree below its
// top separator are processed on separate threads.
#pragma once

#include "linalg/elimination_plan.h"

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <memory>
#include <vector>

namespace ib {

class CholeskyPreconditioner {
 public:
  explicit CholeskyPreconditioner(int threads);
  ~CholeskyPreconditioner();
  CholeskyPreconditioner(CholeskyPreconditioner&&) noexcept;
  CholeskyPreconditioner& operator=(CholeskyPreconditioner&&) noexcept;

  // Factorizes H (n x n, symmetric positive definite; only the lower triangle is read).
  // Throws std::runtime_error if H is not positive definite.
  void factorize(const Eigen::SparseMatrix<double>& H);
  // The same with the elimination order given (order[k]: the unknown eliminated k-th, a
  // permutation of 0..n-1) instead of METIS's, and the symbolic analysis redone, so H's pattern
  // may differ from the last call's. For a caller that rebuilds H often and orders it more
  // cheaply than METIS (on a 17k-vertex grid METIS takes 71 ms, the factorization 14).
  void factorizeInOrder(const Eigen::SparseMatrix<double>& H, const std::vector<int>& order);
  bool factorized() const { return n_ > 0; }

  // From the next factorize() on, H arrives already in the order of an EliminationPlan with
  // these partStart (one entry more than threads): it is factorized as it stands, without METIS,
  // and the solves need no permutation; thread p solves positions [partStart[p], partStart[p+1])
  // and moves only those rows of the right-hand side in and of the result out. Default: unset.
  void setPreordered(std::vector<int> partStart);

  // From the next factorization on, the entries with |L_ij| < tolerance sqrt(L_ii L_jj) are
  // dropped: a sparser, approximate factor (L L^T is still symmetric positive definite), for
  // callers that need only a preconditioner. Default 0: the exact factor.
  void setDropTolerance(double tolerance) { dropTolerance_ = tolerance > 0 ? tolerance : 0.0; }

  // rhs (n x 2) <- H^{-1} rhs.
  void solve(Eigen::MatrixX2d& rhs) const;
  // out = x - H^{-1} g (all n x 2): the global step, without the copies around solve(). out may
  // not be x or g.
  void step(const Eigen::MatrixX2d& x, const Eigen::MatrixX2d& g, Eigen::MatrixX2d& out) const;

  // Entries of L stored (after dropping).
  long factorNonZeros() const { return static_cast<long>(colValue_.size()); }

  // Modifies the factor to that of H + sigma v v^T (sigma = +1 an update, -1 a downdate) without
  // refactorizing (Davis and Hager's sparse rank-one modification, cholesky_update.cpp). v: n x 1
  // in H's numbering, given as rows and values (a repeated row sums). Its outer product must lie
  // in H's pattern (every two of its rows coupled in H), so L keeps its pattern; std::logic_error
  // otherwise, and on a factor with dropped entries. Throws std::runtime_error if a downdate
  // leaves H not positive definite; the factor is then unusable until the next factorize().
  void rankOneUpdate(const std::vector<int>& rows, const std::vector<double>& values, double sigma);
  // Multiply-adds of a rank-one update whose first row (in H's numbering) is `row`: the entries
  // of L on the path from that column to the root of the elimination tree. Comparable with
  // factorizationCost(), the multiply-adds of a numeric factorization (sum of squared column counts).
  long updateCost(int row) const;
  long factorizationCost() const { return factorizationCost_; }

 private:
  // Takes the factor L of the permuted system (perm: row i of H is row perm[i] there; null for
  // none). fresh: L comes from a new analysis (else it has the pattern of the last call's).
  void adopt(const Eigen::SparseMatrix<double>& L, const int* perm, bool fresh);
  void buildSchedule(const Eigen::SparseMatrix<double>& L);
  // The parts and top separator of setPreordered's ranges (std::logic_error if L's elimination
  // tree links two parts).
  void rangeSchedule(const Eigen::SparseMatrix<double>& L);
  // The entries of L kept (all, or those above the drop tolerance), by columns and by rows.
  void storePattern(const Eigen::SparseMatrix<double>& L);
  // out (n x 2) <- H^{-1} b, or position - H^{-1} b when position is given; out may be b.
  void solveWork(const Eigen::MatrixX2d& b, const Eigen::MatrixX2d* position, Eigen::MatrixX2d& out) const;
  // L y = b (forward) and L^T x = y (backward) over the given columns, in place in x (2n,
  // interleaved).
  void forward(const std::vector<int>& columns, double* x) const;
  void backward(const std::vector<int>& columns, double* x) const;
  // solveWork for a preordered H.
  void solvePreordered(const Eigen::MatrixX2d& b, const Eigen::MatrixX2d* position, Eigen::MatrixX2d& out) const;

  struct Analysis;
  std::unique_ptr<Analysis> analysis_;
  int threads_ = 1;
  double dropTolerance_ = 0;
  int n_ = 0;
  std::vector<int> partStart_;            // setPreordered's ranges (empty: not preordered)
  std::vector<int> perm_;                 // row i of rhs goes to perm_[i] of the permuted system
  std::vector<int> colStart_, colRow_;    // L by columns (diagonal first), for L^T x = y
  std::vector<float> colValue_;
  std::vector<int> rowStart_, rowCol_;    // L by rows (diagonal last), for L y = b
  std::vector<float> rowValue_;
  std::vector<int> rowSlot_;              // [entry kept, by columns]: its index in the row storage
  std::vector<int> source_;               // [entry kept, by columns]: its index in L's values
  std::vector<double> inverseDiagonal_;   // 1 / L_jj
  const double* exactValues_ = nullptr;   // L's values in double, owned by the last factorization
                                          // (null when entries are dropped)
  std::vector<double> lower_;             // their copy that rank-one updates modify (empty until
                                          // the first update after a factorization)
  long factorizationCost_ = 0;            // sum over columns of (entries)^2
  std::vector<double> updateWork_;        // n, zero between updates
  std::vector<char> updateMark_;          // n, zero between updates: rows of v
  std::vector<std::vector<int>> part_;    // independent subtrees, one list per thread
  std::vector<int> top_;                  // separator columns above them, done serially
  mutable std::vector<double> work_;      // 2n interleaved
};

}  // namespace ib
