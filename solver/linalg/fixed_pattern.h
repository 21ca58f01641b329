// A sparse matrix assembled again and again from the same list of entries, only the values
// changing: the global matrix of the interpolation solver, refactorized when the weights move.
// The first assembly records where each entry lands; later ones add the values straight into
// place, without building and sorting triplets (at 10k vertices: 0.3 instead of 5 ms).
//
// Use: begin(), then add(row, col, value) for every entry in the same order each time, then
// matrix(). Entries at the same place are summed in the order given, as Eigen's setFromTriplets
// sums them, so the values are the same bit for bit. Only the lower triangle (row >= col) is
// kept: the Cholesky factorization reads nothing else.
#pragma once

#include <Eigen/Sparse>
#include <vector>

namespace ib {

class FixedPatternAssembly {
 public:
  explicit FixedPatternAssembly(int n) : n_(n) {}

  // Starts an assembly: values zeroed (the pattern, once recorded, is kept).
  void begin();
  // Entry k of this assembly. The first assembly records (row, col); later ones must give the
  // same positions in the same order (checked: std::logic_error otherwise).
  void add(int row, int col, double value);
  // The assembled n x n matrix, lower triangle only.
  const Eigen::SparseMatrix<double>& matrix();

 private:
  int n_;
  bool recorded_ = false;                        // the pattern is known
  std::vector<Eigen::Triplet<double>> pending_;  // first assembly: the entries as given (begin() drops them)
  std::vector<int> slot_;                        // [entry]: index into the values, -1 above the diagonal
  std::vector<int> row_, col_;                   // [entry]: its position, for the order check
  size_t next_ = 0;                              // entries added since begin()
  Eigen::SparseMatrix<double> matrix_;
};

}  // namespace ib
