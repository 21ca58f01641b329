#include "placement.h"

#include <cmath>
#include <numeric>

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
}

void PlacementGroups::update(const std::vector<std::pair<int, int>>& links) {
  UnionFind uf(meshComponents_);
  for (const auto& [a, b] : links) uf.join(meshComponent_[a], meshComponent_[b]);
  std::vector<int> componentGroup;
  groupCount_ = labelRoots(uf, meshComponents_, componentGroup);
  for (size_t v = 0; v < label_.size(); ++v) label_[v] = componentGroup[meshComponent_[v]];
}

namespace {

// The common case, one group: the same as below without per-vertex labels.
void alignOne(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& target, const Eigen::VectorXd& mass) {
  const int n = static_cast<int>(x.rows());
  double* px = x.col(0).data();
  double* py = x.col(1).data();
  const double* tx = target.col(0).data();
  const double* ty = target.col(1).data();
  const double* m = mass.data();
  double total = 0, cx = 0, cy = 0, qx = 0, qy = 0;
#pragma omp simd reduction(+ : total, cx, cy, qx, qy)
  for (int v = 0; v < n; ++v) {
    total += m[v];
    cx += m[v] * px[v];
    cy += m[v] * py[v];
    qx += m[v] * tx[v];
    qy += m[v] * ty[v];
  }
  cx /= total;
  cy /= total;
  qx /= total;
  qy /= total;
  double dot = 0, cross = 0;
#pragma omp simd reduction(+ : dot, cross)
  for (int v = 0; v < n; ++v) {
    const double ax = px[v] - cx, ay = py[v] - cy, bx = tx[v] - qx, by = ty[v] - qy;
    dot += m[v] * (ax * bx + ay * by);
    cross += m[v] * (ax * by - ay * bx);
  }
  const double angle = std::atan2(cross, dot), c = std::cos(angle), s = std::sin(angle);
#pragma omp simd
  for (int v = 0; v < n; ++v) {
    const double ax = px[v] - cx, ay = py[v] - cy;
    px[v] = c * ax - s * ay + qx;
    py[v] = s * ax + c * ay + qy;
  }
}

}  // namespace

void alignGroups(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& target, const Eigen::VectorXd& mass,
                 const PlacementGroups& groups) {
  const int g = groups.groupCount();
  if (g == 1) {
    alignOne(x, target, mass);
    return;
  }
  const int* label = groups.label().data();
  const int n = static_cast<int>(x.rows());
  double* px = x.col(0).data();
  double* py = x.col(1).data();
  const double* tx = target.col(0).data();
  const double* ty = target.col(1).data();
  const double* m = mass.data();
  // Per group: total mass, centroids of x and target.
  std::vector<double> total(g, 0.0), cx(g, 0.0), cy(g, 0.0), qx(g, 0.0), qy(g, 0.0);
  for (int v = 0; v < n; ++v) {
    const int k = label[v];
    total[k] += m[v];
    cx[k] += m[v] * px[v];
    cy[k] += m[v] * py[v];
    qx[k] += m[v] * tx[v];
    qy[k] += m[v] * ty[v];
  }
  for (int k = 0; k < g; ++k) {
    cx[k] /= total[k];
    cy[k] /= total[k];
    qx[k] /= total[k];
    qy[k] /= total[k];
  }
  // Optimal angle: atan2(sum m (p x q), sum m (p . q)) with p, q centred source and target.
  std::vector<double> dot(g, 0.0), cross(g, 0.0);
  for (int v = 0; v < n; ++v) {
    const int k = label[v];
    const double ax = px[v] - cx[k], ay = py[v] - cy[k], bx = tx[v] - qx[k], by = ty[v] - qy[k];
    dot[k] += m[v] * (ax * bx + ay * by);
    cross[k] += m[v] * (ax * by - ay * bx);
  }
  std::vector<double> cosine(g), sine(g);
  for (int k = 0; k < g; ++k) {
    const double angle = std::atan2(cross[k], dot[k]);
    cosine[k] = std::cos(angle);
    sine[k] = std::sin(angle);
  }
  for (int v = 0; v < n; ++v) {
    const int k = label[v];
    const double ax = px[v] - cx[k], ay = py[v] - cy[k];
    px[v] = cosine[k] * ax - sine[k] * ay + qx[k];
    py[v] = sine[k] * ax + cosine[k] * ay + qy[k];
  }
}

}  // namespace ib
