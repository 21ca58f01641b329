#include "cholesky_preconditioner.h"

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
  // For factorizeInOrder: the system permuted by the caller's order, factorized as it stands.
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ordered;
};

CholeskyPreconditioner::CholeskyPreconditioner(int threads)
    : analysis_(std::make_unique<Analysis>()), threads_(std::max(1, threads)) {}
CholeskyPreconditioner::~CholeskyPreconditioner() = default;
CholeskyPreconditioner::CholeskyPreconditioner(CholeskyPreconditioner&&) noexcept = default;
CholeskyPreconditioner& CholeskyPreconditioner::operator=(CholeskyPreconditioner&&) noexcept = default;

void CholeskyPreconditioner::factorize(const Eigen::SparseMatrix<double>& H) {
  auto& llt = analysis_->llt;
  const bool first = !analysis_->analyzed;
  if (first) {
    llt.analyzePattern(H);
    analysis_->analyzed = true;
  }
  llt.factorize(H);
  if (llt.info() != Eigen::Success) throw std::runtime_error("global matrix is not positive definite");
  n_ = static_cast<int>(H.rows());
  adopt(llt.matrixL().nestedExpression(), first ? llt.permutationP().indices().data() : nullptr);
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
  ordered.analyzePattern(permuted);
  ordered.factorize(permuted);
  if (ordered.info() != Eigen::Success) throw std::runtime_error("global matrix is not positive definite");
  analysis_->analyzed = false;  // a later factorize() orders afresh
  n_ = n;
  adopt(ordered.matrixL().nestedExpression(), P.indices().data());
}

void CholeskyPreconditioner::adopt(const Eigen::SparseMatrix<double>& L, const int* perm) {
  const int* start = L.outerIndexPtr();
  const double* value = L.valuePtr();
  if (perm) {  // a new order, and so a new elimination tree
    perm_.assign(perm, perm + n_);
    buildSchedule(L);
  }
  if (perm || dropTolerance_ > 0) {
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

void CholeskyPreconditioner::buildSchedule(const Eigen::SparseMatrix<double>& L) {
  // From L's full pattern, before any entry is dropped: dropping one removes a dependency between
  // unknowns, never adds one, so the tree's independent subtrees stay independent.
  const int* start = L.outerIndexPtr();
  const int* row = L.innerIndexPtr();
  // Elimination tree: the parent of column j is the first off-diagonal row of L in column j.
  std::vector<int> parent(n_, -1);
  for (int j = 0; j < n_; ++j)
    if (start[j] + 1 < start[j + 1]) parent[j] = row[start[j] + 1];
  std::vector<long> weight(n_, 0);  // nonzeros in each subtree
  std::vector<std::vector<int>> children(n_);
  std::vector<int> roots;
  for (int j = 0; j < n_; ++j) {
    weight[j] += start[j + 1] - start[j];
    if (parent[j] >= 0) {
      weight[parent[j]] += weight[j];
      children[parent[j]].push_back(j);
    } else {
      roots.push_back(j);
    }
  }
  // Walk down from the root while one child carries almost all the work: that chain is the top
  // separator. Below it, subtrees are independent and go to threads by greedy balancing.
  std::vector<int> level = roots;
  top_.clear();
  while (level.size() == 1 && !children[level[0]].empty()) {
    top_.push_back(level[0]);
    level = children[level[0]];
  }
  std::sort(level.begin(), level.end(), [&](int a, int b) { return weight[a] > weight[b]; });
  part_.assign(threads_, {});
  std::vector<long> load(threads_, 0);
  std::vector<int> owner(n_, -1), stack;
  for (int root : level) {
    const int t = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[t] += weight[root];
    stack = {root};
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      owner[v] = t;
      for (int c : children[v]) stack.push_back(c);
    }
  }
  for (int j = 0; j < n_; ++j)
    if (owner[j] >= 0) part_[owner[j]].push_back(j);  // ascending: children before parents
  std::reverse(top_.begin(), top_.end());             // ascending as well
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

void CholeskyPreconditioner::solveWork(const Eigen::MatrixX2d& b, const Eigen::MatrixX2d* position,
                                       Eigen::MatrixX2d& out) const {
  double* x = work_.data();
  // L y = b, by rows: y_j = (b_j - sum_{k<j} L_jk y_k) / L_jj reads only descendants of j.
  const auto forward = [&](const std::vector<int>& columns) {
    for (int j : columns) {
      const int diag = rowStart_[j + 1] - 1;
      const auto [a, c] = dotPair(&rowCol_[rowStart_[j]], &rowValue_[rowStart_[j]], diag - rowStart_[j], x);
      x[2 * j] = (x[2 * j] - a) * inverseDiagonal_[j];
      x[2 * j + 1] = (x[2 * j + 1] - c) * inverseDiagonal_[j];
    }
  };
  // L^T x = y, by columns in reverse: x_j = (y_j - sum_{i>j} L_ij x_i) / L_jj reads ancestors.
  const auto backward = [&](const std::vector<int>& columns) {
    for (auto it = columns.rbegin(); it != columns.rend(); ++it) {
      const int j = *it, first = colStart_[j] + 1;
      const auto [a, c] = dotPair(&colRow_[first], &colValue_[first], colStart_[j + 1] - first, x);
      x[2 * j] = (x[2 * j] - a) * inverseDiagonal_[j];
      x[2 * j + 1] = (x[2 * j + 1] - c) * inverseDiagonal_[j];
    }
  };
  // b goes into the permuted, interleaved system and the result comes out of it on all threads,
  // in the regions of the subtree solves. Every load comes before the first write, so out may be b.
  const int parts = static_cast<int>(part_.size());
#pragma omp parallel num_threads(parts)
  {
#pragma omp for schedule(static)
    for (int i = 0; i < n_; ++i) {
      x[2 * perm_[i]] = b(i, 0);
      x[2 * perm_[i] + 1] = b(i, 1);
    }
    // The team may have fewer threads than parts.
    for (int p = omp_get_thread_num(); p < parts; p += omp_get_num_threads()) forward(part_[p]);
  }
  forward(top_);
  backward(top_);
#pragma omp parallel num_threads(parts)
  {
    for (int p = omp_get_thread_num(); p < parts; p += omp_get_num_threads()) backward(part_[p]);
#pragma omp barrier
#pragma omp for schedule(static)
    for (int i = 0; i < n_; ++i) {
      const double* solved = x + 2 * perm_[i];
      out(i, 0) = position ? (*position)(i, 0) - solved[0] : solved[0];
      out(i, 1) = position ? (*position)(i, 1) - solved[1] : solved[1];
    }
  }
}

}  // namespace ib
