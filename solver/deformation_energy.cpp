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
  double c, s;
  closestRotation(F(0, 0), F(0, 1), F(1, 0), F(1, 1), c, s);
  Eigen::Matrix2d R;
  R << c, -s, s, c;
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
  rest_.resize(static_cast<size_t>(t) * m * 5);
  for (int c = 0; c < 3; ++c) {
    corner_[c].resize(t);
    for (int k = 0; k < t; ++k) corner_[c][k] = triangles_[k][c];
  }
  for (int k = 0; k < t; ++k) {
    for (int i = 0; i < m; ++i) {
      const Eigen::Matrix2d D = edgeMatrix(keys[i], triangles_[k]);
      const double area = 0.5 * D.determinant();
      if (!(area > 0))
        throw InputError("triangle " + std::to_string(k) + " is degenerate or inverted in key " + std::to_string(i));
      const Eigen::Matrix2d B = D.inverse();
      double* r = rest_.data() + static_cast<size_t>(i) * 5 * t;  // the layout restOf() reads
      r[k] = B(0, 0);
      r[t + k] = B(1, 0);
      r[2 * t + k] = B(0, 1);
      r[3 * t + k] = B(1, 1);
      r[4 * t + k] = kappa(k) * area;
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
  const int t = triangleCount();
  for (int k = 0; k < t; ++k)
    for (size_t a = 0; a < keys.index.size(); ++a) {
      const double* r = restOf(keys.index[a]);
      Eigen::Matrix2d B;
      B << r[k], r[2 * t + k], r[t + k], r[3 * t + k];
      M[k] += 2.0 * keys.weight[a] * r[4 * t + k] * B * B.transpose();
    }
  return M;
}

double DeformationEnergy::evaluate(const Eigen::MatrixX2d& x, const ActiveKeys& keys, Eigen::MatrixX2d& gradient,
                                   int threads) const {
  const int t = triangleCount(), n = static_cast<int>(x.rows());
  const int active = static_cast<int>(keys.index.size());
  const double* px = x.col(0).data();
  const double* py = x.col(1).data();
  // Per-triangle gradient blocks dW_D/dD_t, one array per entry so the loop vectorizes.
  blocks_.resize(4 * static_cast<size_t>(t));
  double* G00 = blocks_.data();
  double* G10 = G00 + t;
  double* G01 = G10 + t;
  double* G11 = G01 + t;
  const int* c0 = corner_[0].data();
  const int* c1 = corner_[1].data();
  const int* c2 = corner_[2].data();
  double energy = 0;
#pragma omp parallel num_threads(threads) reduction(+ : energy)
  {
#pragma omp for schedule(static)
    for (int k = 0; k < t; ++k) G00[k] = G10[k] = G01[k] = G11[k] = 0.0;
    for (int a = 0; a < active; ++a) {
      const double* r = restOf(keys.index[a]);  // B00 B10 B01 B11 c
      const double* b00 = r;
      const double* b10 = r + t;
      const double* b01 = r + 2 * t;
      const double* b11 = r + 3 * t;
      const double* cw = r + 4 * t;
      const double w = keys.weight[a];
#pragma omp for simd schedule(static)
      for (int k = 0; k < t; ++k) {
        // D = [x1 - x0, x2 - x0] (columns); F = D B.
        const double d00 = px[c1[k]] - px[c0[k]], d01 = px[c2[k]] - px[c0[k]];
        const double d10 = py[c1[k]] - py[c0[k]], d11 = py[c2[k]] - py[c0[k]];
        const double f00 = d00 * b00[k] + d01 * b10[k], f01 = d00 * b01[k] + d01 * b11[k];
        const double f10 = d10 * b00[k] + d11 * b10[k], f11 = d10 * b01[k] + d11 * b11[k];
        double c, s;
        closestRotation(f00, f01, f10, f11, c, s);
        const double e00 = f00 - c, e01 = f01 + s, e10 = f10 - s, e11 = f11 - c;  // F - R
        const double weight = w * cw[k];
        energy += weight * (e00 * e00 + e01 * e01 + e10 * e10 + e11 * e11);
        // G += 2 w c (F - R) B^T.
        const double two = 2.0 * weight;
        G00[k] += two * (e00 * b00[k] + e01 * b01[k]);
        G01[k] += two * (e00 * b10[k] + e01 * b11[k]);
        G10[k] += two * (e10 * b00[k] + e11 * b01[k]);
        G11[k] += two * (e10 * b10[k] + e11 * b11[k]);
      }
    }
  }
  double* gx = gradient.col(0).data();
  double* gy = gradient.col(1).data();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int v = 0; v < n; ++v) {
    double ax = 0, ay = 0;
    for (int e = incidenceStart_[v]; e < incidenceStart_[v + 1]; ++e) {
      const int k = incidence_[e] / 3;
      switch (incidence_[e] % 3) {
        case 0: ax -= G00[k] + G01[k]; ay -= G10[k] + G11[k]; break;
        case 1: ax += G00[k]; ay += G10[k]; break;
        default: ax += G01[k]; ay += G11[k]; break;
      }
    }
    gx[v] += ax;
    gy[v] += ay;
  }
  return energy;
}

}  // namespace ib
