#include "deformation_energy.h"

#include "error.h"

#include <Eigen/LU>
#include <cmath>

namespace ib {

ActiveKeys activeKeys(const Eigen::VectorXd& w) {
  ActiveKeys keys;
  for (int i = 0; i < w.size(); ++i)
    if (w(i) > 0) {
      keys.index.push_back(i);
      keys.weight.push_back(w(i));
    }
  return keys;
}

Eigen::Matrix2d closestRotation(const Eigen::Matrix2d& F) {
  // Maximizes tr(R^T F) = cos(theta) (F00 + F11) + sin(theta) (F10 - F01).
  const double s = F(0, 0) + F(1, 1), r = F(1, 0) - F(0, 1);
  const double norm2 = s * s + r * r;
  Eigen::Matrix2d R;
  if (!(norm2 > 1e-300)) return Eigen::Matrix2d::Identity();
  const double inverse = 1.0 / std::sqrt(norm2);
  const double c = s * inverse, sn = r * inverse;
  R << c, -sn, sn, c;
  return R;
}

namespace {

Eigen::Matrix2d edgeMatrix(const Eigen::MatrixX2d& x, const Triangle& tri) {
  Eigen::Matrix2d D;
  D.col(0) = (x.row(tri[1]) - x.row(tri[0])).transpose();
  D.col(1) = (x.row(tri[2]) - x.row(tri[0])).transpose();
  return D;
}

}  // namespace

DeformationEnergy::DeformationEnergy(const std::vector<Triangle>& triangles, const std::vector<Eigen::MatrixX2d>& keys,
                                     const Eigen::VectorXd& kappa)
    : triangles_(triangles), keyCount_(static_cast<int>(keys.size())) {
  const int t = triangleCount(), m = keyCount_;
  const int n = keys.empty() ? 0 : static_cast<int>(keys[0].rows());
  restInverse_.resize(static_cast<size_t>(t) * m);
  weight_.resize(static_cast<size_t>(t) * m);
  lumpedArea_ = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < t; ++k) {
    for (int i = 0; i < m; ++i) {
      const Eigen::Matrix2d D = edgeMatrix(keys[i], triangles_[k]);
      const double area = 0.5 * D.determinant();
      if (!(area > 0))
        throw InputError("triangle " + std::to_string(k) + " is degenerate or inverted in key " + std::to_string(i));
      restInverse_[k * m + i] = D.inverse();
      weight_[k * m + i] = kappa(k) * area;
      for (int v : triangles_[k]) lumpedArea_(v) += area / (3.0 * m);
    }
  }
  incidenceStart_.assign(n + 1, 0);
  for (const Triangle& tri : triangles_)
    for (int v : tri) ++incidenceStart_[v + 1];
  for (int v = 0; v < n; ++v) incidenceStart_[v + 1] += incidenceStart_[v];
  incidence_.resize(3 * static_cast<size_t>(t));
  std::vector<int> fill(incidenceStart_.begin(), incidenceStart_.end() - 1);
  for (int k = 0; k < t; ++k)
    for (int c = 0; c < 3; ++c) incidence_[fill[triangles_[k][c]]++] = 3 * k + c;
}

std::vector<Eigen::Matrix2d> DeformationEnergy::metrics(const ActiveKeys& keys) const {
  std::vector<Eigen::Matrix2d> M(triangles_.size(), Eigen::Matrix2d::Zero());
  for (int k = 0; k < triangleCount(); ++k)
    for (size_t a = 0; a < keys.index.size(); ++a) {
      const int i = keys.index[a];
      const Eigen::Matrix2d& B = restInverse_[k * keyCount_ + i];
      M[k] += 2.0 * keys.weight[a] * weight_[k * keyCount_ + i] * B * B.transpose();
    }
  return M;
}

double DeformationEnergy::evaluate(const Eigen::MatrixX2d& x, const ActiveKeys& keys, Eigen::MatrixX2d& gradient,
                                   int threads) const {
  const int t = triangleCount(), m = keyCount_, n = static_cast<int>(x.rows());
  const int active = static_cast<int>(keys.index.size());
  // Interleaved copy of x so a triangle's corners are three cache-friendly reads.
  interleaved_.resize(2 * static_cast<size_t>(n));
  for (int v = 0; v < n; ++v) {
    interleaved_[2 * v] = x(v, 0);
    interleaved_[2 * v + 1] = x(v, 1);
  }
  const double* p = interleaved_.data();
  blocks_.resize(t);  // dW_D / dD_t per triangle
  double energy = 0;
#pragma omp parallel for schedule(static) reduction(+ : energy) num_threads(threads)
  for (int k = 0; k < t; ++k) {
    const Triangle& tri = triangles_[k];
    const double* p0 = p + 2 * tri[0];
    const double* p1 = p + 2 * tri[1];
    const double* p2 = p + 2 * tri[2];
    Eigen::Matrix2d D;
    D << p1[0] - p0[0], p2[0] - p0[0], p1[1] - p0[1], p2[1] - p0[1];
    Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
    for (int a = 0; a < active; ++a) {
      const int idx = k * m + keys.index[a];
      const Eigen::Matrix2d& B = restInverse_[idx];
      const Eigen::Matrix2d F = D * B;
      const Eigen::Matrix2d diff = F - closestRotation(F);
      const double c = keys.weight[a] * weight_[idx];
      energy += c * diff.squaredNorm();
      G.noalias() += (2.0 * c) * diff * B.transpose();
    }
    blocks_[k] = G;
  }
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int v = 0; v < n; ++v) {
    double gx = 0, gy = 0;
    for (int e = incidenceStart_[v]; e < incidenceStart_[v + 1]; ++e) {
      const double* G = blocks_[incidence_[e] / 3].data();  // column-major: G00 G10 G01 G11
      switch (incidence_[e] % 3) {
        case 0: gx -= G[0] + G[2]; gy -= G[1] + G[3]; break;
        case 1: gx += G[0]; gy += G[1]; break;
        default: gx += G[2]; gy += G[3]; break;
      }
    }
    gradient(v, 0) += gx;
    gradient(v, 1) += gy;
  }
  return energy;
}

}  // namespace ib
