#include "testkit/reference_arap.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <stdexcept>
#include <string>

namespace ib {

namespace {

// Edges of a triangle (v0, v1, v2) as vertex slots, opposite v0, v1, v2 in turn.
constexpr int kEdge[3][2] = {{1, 2}, {2, 0}, {0, 1}};

// The rotation maximizing tr(R S) for a 2 x 2 covariance S = sum_e c_e X_e x_e^T (Procrustes,
// through an SVD as libigl's polar_svd does it).
Eigen::Matrix2d bestRotation(const Eigen::Matrix2d& s) {
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(s, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d u = svd.matrixU();
  Eigen::Matrix2d r = svd.matrixV() * u.transpose();
  if (r.determinant() < 0) {
    u.col(1) *= -1;
    r = svd.matrixV() * u.transpose();
  }
  return r;
}

}  // namespace

ReferenceArap::ReferenceArap(const Eigen::MatrixX2d& rest, const std::vector<Triangle>& triangles,
                             const std::vector<int>& handles)
    : n_(static_cast<int>(rest.rows())), t_(static_cast<int>(triangles.size())), triangles_(triangles), rest_(rest) {
  if (handles.empty()) throw std::invalid_argument("reference ARAP: at least one handle vertex is needed");
  std::vector<int> slot(n_, -1);  // >= 0: index among the free vertices; -2: a handle
  for (int h : handles) {
    if (h < 0 || h >= n_) throw std::invalid_argument("reference ARAP: handle " + std::to_string(h) + " is not a vertex");
    slot[h] = -2;
  }
  handles_ = handles;
  for (int v = 0; v < n_; ++v)
    if (slot[v] == -1) {
      slot[v] = static_cast<int>(free_.size());
      free_.push_back(v);
    }
  std::vector<int> handleSlot(n_, -1);
  for (size_t h = 0; h < handles_.size(); ++h) handleSlot[handles_[h]] = static_cast<int>(h);

  std::vector<Eigen::Triplet<double>> csm, k, lff, lfc;
  cot_.resize(t_);
  for (int tri = 0; tri < t_; ++tri) {
    const Triangle& f = triangles_[tri];
    for (int v : f)
      if (v < 0 || v >= n_) throw std::invalid_argument("reference ARAP: triangle " + std::to_string(tri) + " has a bad vertex");
    for (int e = 0; e < 3; ++e) {  // c_e = cot(angle at the opposite corner) / 2
      const Eigen::Vector2d a = rest.row(f[kEdge[e][0]]) - rest.row(f[e]);
      const Eigen::Vector2d b = rest.row(f[kEdge[e][1]]) - rest.row(f[e]);
      const double cross = a.x() * b.y() - a.y() * b.x();
      if (!(cross > 1e-14 * (a.squaredNorm() + b.squaredNorm())))
        throw std::invalid_argument("reference ARAP: triangle " + std::to_string(tri) + " is degenerate or inverted");
      cot_[tri](e) = 0.5 * a.dot(b) / cross;
    }
    for (int e = 0; e < 3; ++e) {
      const int i = f[kEdge[e][0]], j = f[kEdge[e][1]];
      const double c = cot_[tri](e);
      const Eigen::Vector2d edge = rest.row(i) - rest.row(j);
      for (int d = 0; d < 2; ++d) {
        csm.emplace_back(d * t_ + tri, d * n_ + i, c * edge(d));
        csm.emplace_back(d * t_ + tri, d * n_ + j, -c * edge(d));
        for (int b = 0; b < 2; ++b) {
          k.emplace_back(d * n_ + i, (2 * d + b) * t_ + tri, c * edge(b));
          k.emplace_back(d * n_ + j, (2 * d + b) * t_ + tri, -c * edge(b));
        }
      }
      // L += c (e_i - e_j)(e_i - e_j)^T, split into free and pinned columns.
      const int ends[2] = {i, j};
      for (int r : ends)
        for (int col : ends) {
          if (slot[r] < 0) continue;
          const double value = r == col ? c : -c;
          if (slot[col] >= 0) lff.emplace_back(slot[r], slot[col], value);
          else lfc.emplace_back(slot[r], handleSlot[col], value);
        }
    }
  }
  csm_.resize(2 * t_, 2 * n_);
  csm_.setFromTriplets(csm.begin(), csm.end());
  k_.resize(2 * n_, 4 * t_);
  k_.setFromTriplets(k.begin(), k.end());
  const int freeCount = static_cast<int>(free_.size());
  lff_.resize(freeCount, freeCount);
  lff_.setFromTriplets(lff.begin(), lff.end());
  lfc_.resize(freeCount, static_cast<int>(handles_.size()));
  lfc_.setFromTriplets(lfc.begin(), lfc.end());
  llt_.compute(lff_);
  if (llt_.info() != Eigen::Success)
    throw std::invalid_argument("reference ARAP: the free-vertex system is singular (a part of the mesh has no handle)");
}

Eigen::VectorXd ReferenceArap::rotationsColumn(const Eigen::MatrixX2d& x) const {
  Eigen::MatrixX2d stacked(2 * n_, 2);  // libigl multiplies the scatter matrix by [x; x]
  stacked << x, x;
  const Eigen::MatrixX2d s = csm_ * stacked;
  Eigen::VectorXd rotations(4 * t_);
  for (int tri = 0; tri < t_; ++tri) {
    Eigen::Matrix2d covariance;
    covariance << s.row(tri), s.row(t_ + tri);
    const Eigen::Matrix2d r = bestRotation(covariance);
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) rotations((2 * a + b) * t_ + tri) = r(a, b);
  }
  return rotations;
}

void ReferenceArap::iterate(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& handlePositions) const {
  for (size_t h = 0; h < handles_.size(); ++h) x.row(handles_[h]) = handlePositions.row(h);
  const Eigen::VectorXd b = k_ * rotationsColumn(x);
  const int freeCount = static_cast<int>(free_.size());
  for (int a = 0; a < 2; ++a) {
    Eigen::VectorXd rhs(freeCount);
    for (int f = 0; f < freeCount; ++f) rhs(f) = b(a * n_ + free_[f]);
    rhs -= lfc_ * handlePositions.col(a);
    const Eigen::VectorXd solved = llt_.solve(rhs);
    for (int f = 0; f < freeCount; ++f) x(free_[f], a) = solved(f);
  }
}

double ReferenceArap::energy(const Eigen::MatrixX2d& x) const {
  const Eigen::VectorXd rotations = rotationsColumn(x);
  double total = 0;
  for (int tri = 0; tri < t_; ++tri) {
    Eigen::Matrix2d r;
    r << rotations(tri), rotations(t_ + tri), rotations(2 * t_ + tri), rotations(3 * t_ + tri);
    for (int e = 0; e < 3; ++e) {
      const int i = triangles_[tri][kEdge[e][0]], j = triangles_[tri][kEdge[e][1]];
      const Eigen::Vector2d deformed = (x.row(i) - x.row(j)).transpose();
      const Eigen::Vector2d restEdge = (rest_.row(i) - rest_.row(j)).transpose();
      total += cot_[tri](e) * (deformed - r * restEdge).squaredNorm();
    }
  }
  return total;
}

}  // namespace ib
