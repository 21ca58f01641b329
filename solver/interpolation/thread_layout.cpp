#include "interpolation/thread_layout.h"

#include "linalg/cholesky_preconditioner.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <numeric>

namespace ib {

namespace {

// A symmetric positive definite matrix with H's pattern (mesh edges, and the four vertices of
// every cohesive pair coupled): a graph Laplacian plus the identity. Lower triangle.
Eigen::SparseMatrix<double> patternOfH(const Multimesh& mesh) {
  const int n = mesh.vertexCount();
  std::vector<Eigen::Triplet<double>> entries;
  const auto couple = [&](int a, int b) {
    if (a != b) entries.emplace_back(std::max(a, b), std::min(a, b), -1.0);
  };
  for (const auto& [a, b] : mesh.edges()) couple(a, b);
  for (int i = 0; i < mesh.keyCount(); ++i)
    for (const CohesivePair& p : mesh.cohesivePairs(i)) {
      const int v[4] = {p.a, p.b, p.c, p.d};
      for (int r = 0; r < 4; ++r)
        for (int c = r + 1; c < 4; ++c) couple(v[r], v[c]);
    }
  // Diagonally dominant: 1 plus the entries' magnitudes in the row (repeated couplings add up).
  std::vector<double> diagonal(n, 1.0);
  for (const auto& e : entries) {
    diagonal[e.row()] -= e.value();
    diagonal[e.col()] -= e.value();
  }
  for (int v = 0; v < n; ++v) entries.emplace_back(v, v, diagonal[v]);
  Eigen::SparseMatrix<double> H(n, n);
  H.setFromTriplets(entries.begin(), entries.end());
  return H;
}

// Inner boundaries of a split rounded to whole 64-byte lines of doubles and floats (16 rows):
// vector loops over a block that starts mid-line were measured 27% slower (Anderson's passes at
// 10k vertices).
RowSplit alignedSplit(std::vector<int> start) {
  const int size = start.back();
  for (size_t p = 1; p + 1 < start.size(); ++p) start[p] = std::min((start[p] + 8) / 16 * 16, size);
  return RowSplit(std::move(start));
}

}  // namespace

ThreadLayout threadLayout(const Multimesh& mesh, int threads) {
  EliminationPlan plan = planElimination(patternOfH(mesh), threads);
  const int n = mesh.vertexCount();
  ThreadLayout layout{renumbered(mesh, plan.order), std::move(plan.order), std::move(plan.partStart), {}, {}, {}, {}, {}};
  // Thread p owns its part of the factor's unknowns; the last also the top separator.
  std::vector<int> vertexStart = layout.partStart;
  vertexStart.back() = n;
  layout.vertices = alignedSplit(vertexStart);
  // A triangle goes to the thread owning its lowest vertex; by that vertex within a thread.
  const std::vector<Triangle> all = layout.mesh.triangles();
  std::vector<int> owner(n);
  for (int p = 0; p < threads; ++p)
    for (int v = layout.vertices.begin(p); v < layout.vertices.end(p); ++v) owner[v] = p;
  const auto lowest = [&](int t) { return std::min({all[t][0], all[t][1], all[t][2]}); };
  std::vector<int> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lowest(a) < lowest(b); });
  std::vector<int> triangleStart(static_cast<size_t>(threads) + 1, 0);
  layout.kappa.resize(static_cast<Eigen::Index>(all.size()));
  for (int t : order) {
    ++triangleStart[owner[lowest(t)] + 1];
    layout.kappa(static_cast<Eigen::Index>(layout.triangles.size())) = layout.mesh.stiffness(t);
    layout.triangles.push_back(all[t]);
    layout.triangleOriginalOf.push_back(t);  // renumbered() keeps the triangles' order
  }
  for (int p = 0; p < threads; ++p) triangleStart[p + 1] += triangleStart[p];
  layout.triangleSplit = alignedSplit(triangleStart);
  return layout;
}

Eigen::MatrixX2d toLayout(const Eigen::MatrixX2d& x, const std::vector<int>& originalOf) {
  Eigen::MatrixX2d out(x.rows(), 2);
  for (Eigen::Index k = 0; k < x.rows(); ++k) out.row(k) = x.row(originalOf[k]);
  return out;
}

Eigen::MatrixX2d fromLayout(const Eigen::MatrixX2d& x, const std::vector<int>& originalOf) {
  Eigen::MatrixX2d out(x.rows(), 2);
  for (Eigen::Index k = 0; k < x.rows(); ++k) out.row(originalOf[k]) = x.row(k);
  return out;
}

}  // namespace ib
