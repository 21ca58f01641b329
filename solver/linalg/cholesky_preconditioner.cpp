#include "linalg/cholesky_preconditioner.h"

#include "core/thread_block.h"

#include <iostream>  // Eigen's MetisSupport reports through std::cerr without including it
#include <Eigen/MetisSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <omp.h>
#include <stdexcept>
#include <utility>

namespace ib {

struct CholeskyPreconditioner::Analysis {
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::MetisOrdering<int>> llt;
  bool analyzed = false;
  // For factorizeInOrder and a preordered H: the system factorized as it stands.
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ordered;
  bool preorderedAnalyzed = false;  // `ordered` holds the analysis of the preordered pattern
};

CholeskyPreconditioner::CholeskyPreconditioner(int threads)
    : analysis_(std::make_unique<Analysis>()), threads_(std::max(1, threads)) {}
CholeskyPreconditioner::~CholeskyPreconditioner() = default;
CholeskyPreconditioner::CholeskyPreconditioner(CholeskyPreconditioner&&) noexcept = default;
CholeskyPreconditioner& CholeskyPreconditioner::operator=(CholeskyPreconditioner&&) noexcept = default;

void CholeskyPreconditioner::setPreordered(std::vector<int> partStart) {
  if (static_cast<int>(partStart.size()) != threads_ + 1)
    throw std::invalid_argument("elimination plan: expected one range per thread");
  partStart_ = std::move(partStart);
  analysis_->analyzed = analysis_->preorderedAnalyzed = false;
}

namespace {

// Factorizes H, and where rounding leaves a pivot <= 0 (stiffness contrasts near the limits
// Interpolator accepts, 1e-9 to 1e9, make H that ill-conditioned), H + delta I with delta from
// 1e-12 to 1e-3 of H's largest diagonal entry: the factor then steps a little shorter along
// H's weakest directions, and the solver's energy safeguards keep every step a descent. Throws when
// even that fails (H not positive definite at all: a bug upstream).
template <typename Solver>
void factorizeShifted(Solver& llt, const Eigen::SparseMatrix<double>& H) {
  llt.setShift(0.0);
  llt.factorize(H);
  if (llt.info() == Eigen::Success) return;
  const double largest = H.diagonal().cwiseAbs().maxCoeff();
  for (double fraction = 1e-12; fraction <= 1e-3 && std::isfinite(largest) && largest > 0; fraction *= 1e3) {
    llt.setShift(fraction * largest);
    llt.factorize(H);
    if (llt.info() == Eigen::Success) return;
  }
  llt.setShift(0.0);
  throw std::runtime_error("global matrix is not positive definite");
}

}  // namespace

void CholeskyPreconditioner::factorize(const Eigen::SparseMatrix<double>& H) {
  exactValues_ = nullptr;  // overwritten below; set again once the factorization succeeds
  if (!partStart_.empty()) {
    auto& llt = analysis_->ordered;
    const bool first = !analysis_->preorderedAnalyzed;
    if (first) {
      if (H.rows() < partStart_.back()) throw std::invalid_argument("elimination plan: larger than the matrix");
      llt.analyzePattern(H);
      analysis_->preorderedAnalyzed = true;
    }
    factorizeShifted(llt, H);
    n_ = static_cast<int>(H.rows());
    adopt(llt.matrixL().nestedExpression(), nullptr, first);
    return;
  }
  auto& llt = analysis_->llt;
  const bool first = !analysis_->analyzed;
  if (first) {
    llt.analyzePattern(H);
    analysis_->analyzed = true;
  }
  factorizeShifted(llt, H);
  n_ = static_cast<int>(H.rows());
  adopt(llt.matrixL().nestedExpression(), first ? llt.permutationP().indices().data() : nullptr, first);
}

void CholeskyPreconditioner::factorizeInOrder(const Eigen::SparseMatrix<double>& H, const std::vector<int>& order) {
  const int n = static_cast<int>(H.rows());
  if (static_cast<int>(order.size()) != n) throw std::invalid_argument("elimination order does not match the matrix");
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(n);
  P.indices().setConstant(-1);
  for (int k = 0; k < n; ++k) {
    if (order[k] < 0 || order[k] >= n || P.indices()[order[k]] >= 0)
      throw std::invalid_argument("elimination order is not a permutation");
    P.indices()[order[k]] = k;
  }
  Eigen::SparseMatrix<double> permuted(n, n);
  permuted.selfadjointView<Eigen::Lower>() = H.selfadjointView<Eigen::Lower>().twistedBy(P);  // P H P^T
  auto& ordered = analysis_->ordered;
  exactValues_ = nullptr;
  ordered.analyzePattern(permuted);
  factorizeShifted(ordered, permuted);
  analysis_->analyzed = analysis_->preorderedAnalyzed = false;  // a later factorize() analyzes afresh
  n_ = n;
  adopt(ordered.matrixL().nestedExpression(), P.indices().data(), true);
}

void CholeskyPreconditioner::adopt(const Eigen::SparseMatrix<double>& L, const int* perm, bool fresh) {
  const int* start = L.outerIndexPtr();
  const double* value = L.valuePtr();
  if (fresh) {  // a new order, and so a new elimination tree
    if (perm) {
      perm_.assign(perm, perm + n_);
      buildSchedule(L);
    } else {
      perm_.clear();
      rangeSchedule(L);
    }
  }
  if (fresh || dropTolerance_ > 0) {
    storePattern(L);
  } else if (static_cast<size_t>(L.nonZeros()) != source_.size()) {
    throw std::logic_error("Cholesky factor: the pattern changed without a new analysis");
  }
  const size_t kept = source_.size();
  colValue_.resize(kept);
  rowValue_.resize(kept);
  for (size_t k = 0; k < kept; ++k) {
    const float v = static_cast<float>(value[source_[k]]);
    colValue_[k] = v;
    rowValue_[rowSlot_[k]] = v;
  }
  // Rank-one updates copy L's values on first use, from the factorization that owns them.
  exactValues_ = dropTolerance_ > 0 ? nullptr : value;
  lower_.clear();
  if (fresh) {
    factorizationCost_ = 0;
    for (int j = 0; j < n_; ++j) factorizationCost_ += static_cast<long>(start[j + 1] - start[j]) * (start[j + 1] - start[j]);
  }
  // Multiplying by 1 / L_jj instead of dividing shortens the dependency chain from one
  // unknown to the next.
  inverseDiagonal_.resize(n_);
  for (int j = 0; j < n_; ++j) inverseDiagonal_[j] = 1.0 / value[start[j]];
  work_.assign(2 * static_cast<size_t>(n_), 0.0);
}

void CholeskyPreconditioner::storePattern(const Eigen::SparseMatrix<double>& L) {
  const int* start = L.outerIndexPtr();
  const int* row = L.innerIndexPtr();
  const double* value = L.valuePtr();
  // By columns: the diagonal first, then the rows kept.
  colStart_.assign(n_ + 1, 0);
  colRow_.clear();
  source_.clear();
  for (int j = 0; j < n_; ++j) {
    const double bound = dropTolerance_ * std::sqrt(value[start[j]]);
    for (int e = start[j]; e < start[j + 1]; ++e) {
      const int i = row[e];
      if (i == j || std::abs(value[e]) >= bound * std::sqrt(value[start[i]])) {
        colRow_.push_back(i);
        source_.push_back(e);
      }
    }
    colStart_[j + 1] = static_cast<int>(colRow_.size());
  }
  // By rows, through a transposition that remembers where each entry went (rowSlot_), so that a
  // refactorization in the same pattern only copies values.
  const size_t kept = colRow_.size();
  rowStart_.assign(n_ + 1, 0);
  for (size_t k = 0; k < kept; ++k) ++rowStart_[colRow_[k] + 1];
  for (int i = 0; i < n_; ++i) rowStart_[i + 1] += rowStart_[i];
  rowCol_.resize(kept);
  rowSlot_.resize(kept);
  std::vector<int> fill(rowStart_.begin(), rowStart_.end() - 1);
  for (int j = 0; j < n_; ++j)  // columns in order: each row's entries by column, diagonal last
    for (int k = colStart_[j]; k < colStart_[j + 1]; ++k) {
      const int at = fill[colRow_[k]]++;
      rowCol_[at] = j;
      rowSlot_[k] = at;
    }
}

namespace {

// The elimination tree of a factor L (n x n, by columns, diagonal first): the parent of column j
// is its first off-diagonal row, -1 for a root.
std::vector<int> eliminationTree(const Eigen::SparseMatrix<double>& L) {
  const int* start = L.outerIndexPtr();
  const int* row = L.innerIndexPtr();
  std::vector<int> parent(L.cols(), -1);
  for (int j = 0; j < L.cols(); ++j)
    if (start[j] + 1 < start[j + 1]) parent[j] = row[start[j] + 1];
  return parent;
}

}  // namespace

void CholeskyPreconditioner::buildSchedule(const Eigen::SparseMatrix<double>& L) {
  // From L's full pattern, before any entry is dropped: dropping one removes a dependency between
  // unknowns, never adds one, so the tree's independent subtrees stay independent.
  const int* start = L.outerIndexPtr();
  std::vector<long> entries(n_);
  for (int j = 0; j < n_; ++j) entries[j] = start[j + 1] - start[j];
  EliminationSchedule schedule = scheduleSubtrees(eliminationTree(L), entries, threads_);
  part_ = std::move(schedule.part);
  top_ = std::move(schedule.top);
}

void CholeskyPreconditioner::rangeSchedule(const Eigen::SparseMatrix<double>& L) {
  // The parts are only independent if no column's parent in the elimination tree lies in
  // another part: true for the pattern the plan was made from, not for one with more couplings.
  const std::vector<int> parent = eliminationTree(L);
  for (int p = 0; p < threads_; ++p)
    for (int j = partStart_[p]; j < partStart_[p + 1]; ++j)
      if (parent[j] >= partStart_[p + 1] && parent[j] < partStart_.back())
        throw std::logic_error("Cholesky factor: H couples two threads' parts of its elimination plan");
  part_.assign(threads_, {});
  for (int p = 0; p < threads_; ++p)
    for (int j = partStart_[p]; j < partStart_[p + 1]; ++j) part_[p].push_back(j);
  top_.clear();
  for (int j = partStart_.back(); j < n_; ++j) top_.push_back(j);
}

namespace {

// sum_k value[k] * (x[2 index[k]], x[2 index[k] + 1]) with four independent accumulator pairs,
// so the sum is not serialized on the latency of one chain of additions.
std::pair<double, double> dotPair(const int* index, const float* value, int count, const double* x) {
  double a0 = 0, a1 = 0, a2 = 0, a3 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0;
  int k = 0;
  for (; k + 4 <= count; k += 4) {
    const double l0 = value[k], l1 = value[k + 1], l2 = value[k + 2], l3 = value[k + 3];
    const double* x0 = x + 2 * index[k];
    const double* x1 = x + 2 * index[k + 1];
    const double* x2 = x + 2 * index[k + 2];
    const double* x3 = x + 2 * index[k + 3];
    a0 += l0 * x0[0];
    b0 += l0 * x0[1];
    a1 += l1 * x1[0];
    b1 += l1 * x1[1];
    a2 += l2 * x2[0];
    b2 += l2 * x2[1];
    a3 += l3 * x3[0];
    b3 += l3 * x3[1];
  }
  for (; k < count; ++k) {
    const double l = value[k];
    a0 += l * x[2 * index[k]];
    b0 += l * x[2 * index[k] + 1];
  }
  return {(a0 + a1) + (a2 + a3), (b0 + b1) + (b2 + b3)};
}

}  // namespace

void CholeskyPreconditioner::solve(Eigen::MatrixX2d& rhs) const { solveWork(rhs, nullptr, rhs); }

void CholeskyPreconditioner::step(const Eigen::MatrixX2d& position, const Eigen::MatrixX2d& g,
                                  Eigen::MatrixX2d& out) const {
  out.resize(n_, 2);
  solveWork(g, &position, out);
}

void CholeskyPreconditioner::forward(const std::vector<int>& columns, double* x) const {
  // L y = b, by rows: y_j = (b_j - sum_{k<j} L_jk y_k) / L_jj reads only descendants of j.
  for (int j : columns) {
    const int diag = rowStart_[j + 1] - 1;
    const auto [a, c] = dotPair(&rowCol_[rowStart_[j]], &rowValue_[rowStart_[j]], diag - rowStart_[j], x);
    x[2 * j] = (x[2 * j] - a) * inverseDiagonal_[j];
    x[2 * j + 1] = (x[2 * j + 1] - c) * inverseDiagonal_[j];
  }
}

void CholeskyPreconditioner::backward(const std::vector<int>& columns, double* x) const {
  // L^T x = y, by columns in reverse: x_j = (y_j - sum_{i>j} L_ij x_i) / L_jj reads ancestors.
  for (auto it = columns.rbegin(); it != columns.rend(); ++it) {
    const int j = *it, first = colStart_[j] + 1;
    const auto [a, c] = dotPair(&colRow_[first], &colValue_[first], colStart_[j + 1] - first, x);
    x[2 * j] = (x[2 * j] - a) * inverseDiagonal_[j];
    x[2 * j + 1] = (x[2 * j + 1] - c) * inverseDiagonal_[j];
  }
}

void CholeskyPreconditioner::solveWork(const Eigen::MatrixX2d& b, const Eigen::MatrixX2d* position,
                                       Eigen::MatrixX2d& out) const {
  if (perm_.empty()) {
    solvePreordered(b, position, out);
    return;
  }
  double* x = work_.data();
  // b goes into the permuted, interleaved system and the result comes out of it on all threads,
  // in the regions of the subtree solves. Every load comes before the first write, so out may be b.
  const int parts = static_cast<int>(part_.size());
#pragma omp parallel num_threads(teamFor(parts))
  {
#pragma omp for schedule(static)
    for (int i = 0; i < n_; ++i) {
      x[2 * perm_[i]] = b(i, 0);
      x[2 * perm_[i] + 1] = b(i, 1);
    }
    // The team may have fewer threads than parts.
    for (int p = omp_get_thread_num(); p < parts; p += omp_get_num_threads()) forward(part_[p], x);
  }
  forward(top_, x);
  backward(top_, x);
#pragma omp parallel num_threads(teamFor(parts))
  {
    for (int p = omp_get_thread_num(); p < parts; p += omp_get_num_threads()) backward(part_[p], x);
#pragma omp barrier
#pragma omp for schedule(static)
    for (int i = 0; i < n_; ++i) {
      const double* solved = x + 2 * perm_[i];
      out(i, 0) = position ? (*position)(i, 0) - solved[0] : solved[0];
      out(i, 1) = position ? (*position)(i, 1) - solved[1] : solved[1];
    }
  }
}

void CholeskyPreconditioner::solvePreordered(const Eigen::MatrixX2d& b, const Eigen::MatrixX2d* position,
                                             Eigen::MatrixX2d& out) const {
  double* x = work_.data();
  // Rows [first, last) of b into the interleaved system, or of the result out of it.
  const auto load = [&](int first, int last) {
    for (int i = first; i < last; ++i) {
      x[2 * i] = b(i, 0);
      x[2 * i + 1] = b(i, 1);
    }
  };
  const auto store = [&](int first, int last) {
    for (int i = first; i < last; ++i) {
      out(i, 0) = position ? (*position)(i, 0) - x[2 * i] : x[2 * i];
      out(i, 1) = position ? (*position)(i, 1) - x[2 * i + 1] : x[2 * i + 1];
    }
  };
  // A part's rows are all its solves read and write: no barrier inside the regions, and each
  // thread touches only the rows it owns. Every load of b comes before the first store, so out
  // may be b.
  const int parts = static_cast<int>(part_.size());
#pragma omp parallel num_threads(teamFor(parts))
  for (int p = omp_get_thread_num(); p < parts; p += omp_get_num_threads()) {
    load(partStart_[p], partStart_[p + 1]);
    forward(part_[p], x);
  }
  load(partStart_.back(), n_);
  forward(top_, x);
  backward(top_, x);
  store(partStart_.back(), n_);
#pragma omp parallel num_threads(teamFor(parts))
  for (int p = omp_get_thread_num(); p < parts; p += omp_get_num_threads()) {
    backward(part_[p], x);
    store(partStart_[p], partStart_[p + 1]);
  }
}

}  // namespace ib
