// Rank-one modification of the sparse factor H = L L^T (Davis and Hager, "Modifying a sparse
// Cholesky factorization", 1999): H + sigma v v^T = L' L'^T, where L' differs from L only in the
// columns on the path from v's first row to the root of the elimination tree. When v v^T lies in
// H's pattern, L' has L's pattern, so the float copies the solves read are refreshed in place.
#include "linalg/cholesky_preconditioner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ib {

namespace {

// The parent of column j in the elimination tree: its first off-diagonal row, -1 at a root.
int parentOf(const std::vector<int>& colStart, const std::vector<int>& colRow, int j) {
  return colStart[j] + 1 < colStart[j + 1] ? colRow[colStart[j] + 1] : -1;
}

}  // namespace

long CholeskyPreconditioner::updateCost(int row) const {
  if (row < 0 || row >= n_) throw std::invalid_argument("rank-one update: row out of range");
  long cost = 0;
  for (int j = perm_.empty() ? row : perm_[row]; j >= 0; j = parentOf(colStart_, colRow_, j))
    cost += colStart_[j + 1] - colStart_[j];
  return cost;
}

void CholeskyPreconditioner::rankOneUpdate(const std::vector<int>& rows, const std::vector<double>& values,
                                           double sigma) {
  if (!exactValues_) throw std::logic_error("rank-one update: needs an exact factor (no dropped entries)");
  if (lower_.empty()) lower_.assign(exactValues_, exactValues_ + colStart_.back());
  if (rows.size() != values.size()) throw std::invalid_argument("rank-one update: rows and values differ in length");
  if (rows.empty()) return;
  std::vector<double>& x = updateWork_;  // v, then what is left of it below the current column
  std::vector<char>& inV = updateMark_;
  x.resize(n_, 0.0);
  inV.resize(n_, 0);
  int first = n_;
  for (int row : rows) {
    if (row < 0 || row >= n_) throw std::invalid_argument("rank-one update: row out of range");
    first = std::min(first, perm_.empty() ? row : perm_[row]);
  }
  // v v^T lies in L's pattern when every other row of v is in column `first`. Then nothing is
  // created further up either: a column's rows below its parent are all rows of the parent's
  // column (the elimination tree's defining property), so what is left of v always fits.
  int outside = 0;
  for (int row : rows) {
    const int i = perm_.empty() ? row : perm_[row];
    outside += i != first && !inV[i];
    inV[i] = 1;
  }
  for (int e = colStart_[first] + 1; e < colStart_[first + 1]; ++e) outside -= inV[colRow_[e]];
  for (int row : rows) inV[perm_.empty() ? row : perm_[row]] = 0;
  if (outside != 0) throw std::logic_error("rank-one update: v v^T is not within the factor's pattern");
  for (size_t k = 0; k < rows.size(); ++k) x[perm_.empty() ? rows[k] : perm_[rows[k]]] += values[k];

  for (int j = first; j >= 0; j = parentOf(colStart_, colRow_, j)) {
    const double xj = x[j];
    x[j] = 0;
    if (xj == 0) continue;  // this column stays; the rows above may still carry v
    const int diag = colStart_[j];
    const double ljj = lower_[diag];
    const double squared = ljj * ljj + sigma * xj * xj;
    if (!(squared > 0) || !std::isfinite(squared)) {
      for (int e = diag; e < colStart_[j + 1]; ++e) x[colRow_[e]] = 0;  // all that is left of v
      throw std::runtime_error("rank-one update: the modified matrix is not positive definite");
    }
    // The rotation that zeroes x_j against L_jj (hyperbolic for a downdate).
    const double r = std::sqrt(squared), c = r / ljj, s = xj / ljj;
    lower_[diag] = r;
    colValue_[diag] = static_cast<float>(r);
    rowValue_[rowSlot_[diag]] = static_cast<float>(r);
    inverseDiagonal_[j] = 1.0 / r;
    for (int e = diag + 1; e < colStart_[j + 1]; ++e) {
      const int i = colRow_[e];
      const double lij = (lower_[e] + sigma * s * x[i]) / c;
      x[i] = c * x[i] - s * lij;
      lower_[e] = lij;
      colValue_[e] = static_cast<float>(lij);
      rowValue_[rowSlot_[e]] = static_cast<float>(lij);
    }
  }
}

}  // namespace ib
