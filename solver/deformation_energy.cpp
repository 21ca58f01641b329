#include "deformation_energy.h"

#include "error.h"
#include "thread_block.h"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

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
  // Incidence grouped by vertex, then by the corner the vertex is: slot 3 v + c.
  incidenceStart_.assign(3 * static_cast<size_t>(n) + 1, 0);
  for (const Triangle& tri : triangles_)
    for (int c = 0; c < 3; ++c) ++incidenceStart_[3 * tri[c] + c + 1];
  for (size_t slot = 0; slot + 1 < incidenceStart_.size(); ++slot) incidenceStart_[slot + 1] += incidenceStart_[slot];
  incidence_.resize(3 * static_cast<size_t>(t));
  std::vector<int> fill(incidenceStart_.begin(), incidenceStart_.end() - 1);
  for (int k = 0; k < t; ++k)
    for (int c = 0; c < 3; ++c) incidence_[fill[3 * triangles_[k][c] + c]++] = k;
}

Eigen::Matrix2d DeformationEnergy::metric(int k, const ActiveKeys& keys) const {
  const int t = triangleCount();
  Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
  for (size_t a = 0; a < keys.index.size(); ++a) {
    const double* r = restOf(keys.index[a]);
    Eigen::Matrix2d B;
    B << r[k], r[2 * t + k], r[t + k], r[3 * t + k];
    M += 2.0 * keys.weight[a] * r[4 * t + k] * B * B.transpose();
  }
  return M;
}

double DeformationEnergy::evaluate(const Eigen::MatrixX2d& x, const ActiveKeys& keys, Eigen::MatrixX2d& gradient,
                                   const RowSplit& vertices, const RowSplit& triangles) const {
  const int t = triangleCount(), n = static_cast<int>(x.rows());
  if (vertices.size() != n || triangles.size() != t || vertices.threads() != triangles.threads())
    throw std::invalid_argument("deformation energy: the thread split does not match the mesh");
  const int active = static_cast<int>(keys.index.size());
  const double* px = x.col(0).data();
  const double* py = x.col(1).data();
  // Scratch, one array per entry so the loops vectorize: edge matrices D_t, then the gradient
  // blocks dW_D/dD_t.
  scratch_.resize(8 * static_cast<size_t>(t));
  double* D00 = scratch_.data();
  double* D01 = D00 + t;
  double* D10 = D01 + t;
  double* D11 = D10 + t;
  double* G00 = D11 + t;
  double* G01 = G00 + t;
  double* G10 = G01 + t;
  double* G11 = G10 + t;
  const int* c0 = corner_[0].data();
  const int* c1 = corner_[1].data();
  const int* c2 = corner_[2].data();
  // Each block of triangles sums its own energy; the sums are added in block order afterwards, so
  // the energy is bit-identical from run to run (an OpenMP reduction adds them in arrival order).
  const int blocks = vertices.threads();
  std::vector<double> partial(static_cast<size_t>(blocks), 0.0);
#pragma omp parallel num_threads(blocks)
  {
    // The team may have fewer threads than blocks.
    const int self = omp_get_thread_num(), team = omp_get_num_threads();
    for (int p = self; p < blocks; p += team) {
      double energy = 0;
      // Every loop over this block's triangles reads only entries it wrote itself: no barrier
      // between them.
      const int begin = triangles.begin(p), end = triangles.end(p);
#pragma omp simd
      for (int k = begin; k < end; ++k) {
        D00[k] = px[c1[k]] - px[c0[k]];
        D01[k] = px[c2[k]] - px[c0[k]];
        D10[k] = py[c1[k]] - py[c0[k]];
        D11[k] = py[c2[k]] - py[c0[k]];
        G00[k] = G01[k] = G10[k] = G11[k] = 0.0;
      }
      for (int a = 0; a < active; ++a) {
        const double* r = restOf(keys.index[a]);  // B00 B10 B01 B11 c
        const double* b00 = r;
        const double* b10 = r + t;
        const double* b01 = r + 2 * t;
        const double* b11 = r + 3 * t;
        const double* cw = r + 4 * t;
        const double w = keys.weight[a];
#pragma omp simd reduction(+ : energy)
        for (int k = begin; k < end; ++k) {
          // F = D B, R its closest rotation, G += 2 w c (F - R) B^T.
          const double f00 = D00[k] * b00[k] + D01[k] * b10[k], f01 = D00[k] * b01[k] + D01[k] * b11[k];
          const double f10 = D10[k] * b00[k] + D11[k] * b10[k], f11 = D10[k] * b01[k] + D11[k] * b11[k];
          double c, s;
          closestRotation(f00, f01, f10, f11, c, s);
          const double e00 = f00 - c, e01 = f01 + s, e10 = f10 - s, e11 = f11 - c;  // F - R
          const double weight = w * cw[k];
          energy += weight * (e00 * e00 + e01 * e01 + e10 * e10 + e11 * e11);
          const double two = 2.0 * weight;
          G00[k] += two * (e00 * b00[k] + e01 * b01[k]);
          G01[k] += two * (e00 * b10[k] + e01 * b11[k]);
          G10[k] += two * (e10 * b00[k] + e11 * b01[k]);
          G11[k] += two * (e10 * b10[k] + e11 * b11[k]);
        }
      }
      partial[p] = energy;
    }
#pragma omp barrier
    // dW/dx_v: corner 0 of a triangle receives -(G e_0 + G e_1), corners 1 and 2 the columns of G.
    double* gx = gradient.col(0).data();
    double* gy = gradient.col(1).data();
    const int* at = incidenceStart_.data();
    for (int p = self; p < blocks; p += team)
      for (int v = vertices.begin(p); v < vertices.end(p); ++v) {
        double ax = 0, ay = 0;
        for (int e = at[3 * v]; e < at[3 * v + 1]; ++e) {
          const int k = incidence_[e];
          ax -= G00[k] + G01[k];
          ay -= G10[k] + G11[k];
        }
        for (int e = at[3 * v + 1]; e < at[3 * v + 2]; ++e) {
          ax += G00[incidence_[e]];
          ay += G10[incidence_[e]];
        }
        for (int e = at[3 * v + 2]; e < at[3 * v + 3]; ++e) {
          ax += G01[incidence_[e]];
          ay += G11[incidence_[e]];
        }
        gx[v] += ax;
        gy[v] += ay;
      }
  }
  double energy = 0;
  for (double p : partial) energy += p;
  return energy;
}

}  // namespace ib
