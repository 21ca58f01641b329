#include "linalg/fixed_pattern.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ib {

void FixedPatternAssembly::begin() {
  next_ = 0;
  pending_.clear();
  if (recorded_) std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
}

void FixedPatternAssembly::add(int row, int col, double value) {
  const size_t k = next_++;
  if (!recorded_) {
    pending_.emplace_back(row, col, value);
    return;
  }
  if (k >= slot_.size() || row_[k] != row || col_[k] != col)
    throw std::logic_error("fixed pattern assembly: entry " + std::to_string(k) + " is not where it was first");
  if (slot_[k] >= 0) matrix_.valuePtr()[slot_[k]] += value;
}

const Eigen::SparseMatrix<double>& FixedPatternAssembly::matrix() {
  if (recorded_) {
    if (next_ != slot_.size())
      throw std::logic_error("fixed pattern assembly: " + std::to_string(next_) + " entries instead of " +
                             std::to_string(slot_.size()));
    return matrix_;
  }
  // The first assembly: Eigen builds the matrix (and so the pattern and the first values), then
  // every entry's place in it is looked up once.
  std::vector<Eigen::Triplet<double>> lower;
  lower.reserve(pending_.size());
  for (const auto& t : pending_)
    if (t.row() >= t.col()) lower.push_back(t);
  matrix_.resize(n_, n_);
  matrix_.setFromTriplets(lower.begin(), lower.end());
  matrix_.makeCompressed();
  slot_.assign(pending_.size(), -1);
  row_.resize(pending_.size());
  col_.resize(pending_.size());
  const int* start = matrix_.outerIndexPtr();
  const int* rows = matrix_.innerIndexPtr();
  for (size_t k = 0; k < pending_.size(); ++k) {
    const int r = pending_[k].row(), c = pending_[k].col();
    row_[k] = r;
    col_[k] = c;
    if (r < c) continue;
    slot_[k] = static_cast<int>(std::lower_bound(rows + start[c], rows + start[c + 1], r) - rows);
  }
  pending_.clear();
  pending_.shrink_to_fit();
  recorded_ = true;
  return matrix_;
}

}  // namespace ib
