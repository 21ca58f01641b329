#include "interpolation/placement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <omp.h>

namespace ib {

namespace {

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

// Dense labels 0..count-1 for the roots of uf over `size` items.
int labelRoots(UnionFind& uf, int size, std::vector<int>& label) {
  std::vector<int> id(size, -1);
  label.resize(size);
  int count = 0;
  for (int v = 0; v < size; ++v) {
    const int r = uf.find(v);
    if (id[r] < 0) id[r] = count++;
    label[v] = id[r];
  }
  return count;
}

}  // namespace

PlacementGroups::PlacementGroups(int vertexCount, const std::vector<std::pair<int, int>>& meshEdges) {
  UnionFind uf(vertexCount);
  for (const auto& [a, b] : meshEdges) uf.join(a, b);
  meshComponents_ = labelRoots(uf, vertexCount, meshComponent_);
  label_ = meshComponent_;
  groupCount_ = meshComponents_;
  buildMembers();
}

void PlacementGroups::update(const std::vector<std::pair<int, int>>& links) {
  UnionFind uf(meshComponents_);
  for (const auto& [a, b] : links) uf.join(meshComponent_[a], meshComponent_[b]);
  std::vector<int> componentGroup;
  groupCount_ = labelRoots(uf, meshComponents_, componentGroup);
  for (size_t v = 0; v < label_.size(); ++v) label_[v] = componentGroup[meshComponent_[v]];
  buildMembers();
}

void PlacementGroups::buildMembers() {
  memberStart_.assign(groupCount_ + 1, 0);
  for (int g : label_) ++memberStart_[g + 1];
  for (int k = 0; k < groupCount_; ++k) memberStart_[k + 1] += memberStart_[k];
  members_.resize(label_.size());
  std::vector<int> fill(memberStart_.begin(), memberStart_.end() - 1);
  for (size_t v = 0; v < label_.size(); ++v) members_[fill[label_[v]]++] = static_cast<int>(v);
}

namespace {

// Aligns the vertices index(0..count-1) of x rigidly to target with weights weight(v):
// weighted centroids, then the angle atan2(sum m p x q, sum m p . q) of the centred point sets
// p (x) and q (target). A weight of 1.0 for every vertex gives the unweighted fit bit for bit.
template <class Index, class Weight>
void alignSet(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& target, int count, Index index, Weight weight) {
  double* px = x.col(0).data();
  double* py = x.col(1).data();
  const double* tx = target.col(0).data();
  const double* ty = target.col(1).data();
  // The sums vectorize (simd reductions: a fixed order, the same every run).
  double mass = 0, cx = 0, cy = 0, qx = 0, qy = 0;
#pragma omp simd reduction(+ : mass, cx, cy, qx, qy)
  for (int i = 0; i < count; ++i) {
    const int v = index(i);
    const double m = weight(v);
    mass += m;
    cx += m * px[v];
    cy += m * py[v];
    qx += m * tx[v];
    qy += m * ty[v];
  }
  cx /= mass;
  cy /= mass;
  qx /= mass;
  qy /= mass;
  double dot = 0, cross = 0;
#pragma omp simd reduction(+ : dot, cross)
  for (int i = 0; i < count; ++i) {
    const int v = index(i);
    const double m = weight(v);
    const double ax = px[v] - cx, ay = py[v] - cy, bx = tx[v] - qx, by = ty[v] - qy;
    dot += m * (ax * bx + ay * by);
    cross += m * (ax * by - ay * bx);
  }
  const double angle = std::atan2(cross, dot), c = std::cos(angle), s = std::sin(angle);
#pragma omp simd
  for (int i = 0; i < count; ++i) {
    const int v = index(i);
    const double ax = px[v] - cx, ay = py[v] - cy;
    px[v] = c * ax - s * ay + qx;
    py[v] = s * ax + c * ay + qy;
  }
}

// alignSet over all vertices, each block of rows summed and moved by one thread. The partial sums
// are added in block order by every thread alike: bit-identical from run to run.
template <class Weight>
void alignAll(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& target, const RowSplit& rows, Weight weight) {
  double* px = x.col(0).data();
  double* py = x.col(1).data();
  const double* tx = target.col(0).data();
  const double* ty = target.col(1).data();
  const int blocks = rows.threads();
  std::vector<std::array<double, 5>> centroids(static_cast<size_t>(blocks));
  std::vector<std::array<double, 2>> turns(static_cast<size_t>(blocks));
#pragma omp parallel num_threads(teamFor(blocks))
  {
    // The team may have fewer threads than blocks.
    const int self = omp_get_thread_num(), team = omp_get_num_threads();
    for (int p = self; p < blocks; p += team) {
      double mass = 0, cx = 0, cy = 0, qx = 0, qy = 0;
#pragma omp simd reduction(+ : mass, cx, cy, qx, qy)
      for (int v = rows.begin(p); v < rows.end(p); ++v) {
        const double m = weight(v);
        mass += m;
        cx += m * px[v];
        cy += m * py[v];
        qx += m * tx[v];
        qy += m * ty[v];
      }
      centroids[p] = {cx, cy, qx, qy, mass};
    }
#pragma omp barrier
    std::array<double, 5> centre{};
    for (const auto& c : centroids)
      for (int k = 0; k < 5; ++k) centre[k] += c[k];
    for (int k = 0; k < 4; ++k) centre[k] /= centre[4];
    // Plain variables, not a structured binding: clang cannot use a binding inside omp simd.
    const double cx = centre[0], cy = centre[1], qx = centre[2], qy = centre[3];
    for (int p = self; p < blocks; p += team) {
      double dot = 0, cross = 0;
#pragma omp simd reduction(+ : dot, cross)
      for (int v = rows.begin(p); v < rows.end(p); ++v) {
        const double m = weight(v);
        const double ax = px[v] - cx, ay = py[v] - cy, bx = tx[v] - qx, by = ty[v] - qy;
        dot += m * (ax * bx + ay * by);
        cross += m * (ax * by - ay * bx);
      }
      turns[p] = {dot, cross};
    }
#pragma omp barrier
    double dot = 0, cross = 0;
    for (const auto& t : turns) {
      dot += t[0];
      cross += t[1];
    }
    const double angle = std::atan2(cross, dot), c = std::cos(angle), s = std::sin(angle);
    for (int p = self; p < blocks; p += team) {
#pragma omp simd
      for (int v = rows.begin(p); v < rows.end(p); ++v) {
        const double ax = px[v] - cx, ay = py[v] - cy;
        px[v] = c * ax - s * ay + qx;
        py[v] = s * ax + c * ay + qy;
      }
    }
  }
}

template <class Weight>
void alignGroupsWeighted(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& target, const PlacementGroups& groups,
                         const RowSplit& rows, Weight weight) {
  if (groups.groupCount() == 1 && rows.threads() > 1 && rows.size() == x.rows()) {
    alignAll(x, target, rows, weight);
    return;
  }
  if (groups.groupCount() == 1) {  // the common case, without indirection
    alignSet(x, target, static_cast<int>(x.rows()), [](int i) { return i; }, weight);
    return;
  }
  const auto& start = groups.memberStart();
  const auto& members = groups.members();
  for (int k = 0; k < groups.groupCount(); ++k) {
    const int* list = members.data() + start[k];
    alignSet(x, target, start[k + 1] - start[k], [list](int i) { return list[i]; }, weight);
  }
}

}  // namespace

void alignGroups(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& target, const PlacementGroups& groups,
                 const RowSplit& rows, const Eigen::VectorXd& weights) {
  if (weights.size() == 0) {
    alignGroupsWeighted(x, target, groups, rows, [](int) { return 1.0; });
    return;
  }
  const double* m = weights.data();
  alignGroupsWeighted(x, target, groups, rows, [m](int v) { return m[v]; });
}

Eigen::VectorXd stillnessWeights(const std::vector<Eigen::MatrixX2d>& keys, double pixel) {
  const Eigen::Index n = keys.empty() ? 0 : keys[0].rows();
  Eigen::VectorXd m(n);
  for (Eigen::Index v = 0; v < n; ++v) {
    double spread = 0;  // the largest distance of a key's position from key 0's, in pixels
    for (const auto& X : keys) spread = std::max(spread, (X.row(v) - keys[0].row(v)).norm() / pixel);
    m(v) = 1.0 + kStillWeight * std::exp(-(spread / kStillRadius) * (spread / kStillRadius));
  }
  return m / m.sum();
}

}  // namespace ib
