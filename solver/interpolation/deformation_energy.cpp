#include "interpolation/deformation_energy.h"

#include "core/error.h"
#include "core/thread_block.h"

#include <Eigen/LU>
#include <algorithm>
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
    }
  }
  setStiffness(keys, kappa);
}

void DeformationEnergy::setStiffness(const std::vector<Eigen::MatrixX2d>& keys, const Eigen::VectorXd& kappa) {
  const int t = triangleCount();
  if (static_cast<int>(keys.size()) != keyCount_ || kappa.size() != t)
    throw std::invalid_argument("deformation energy: stiffness for the wrong number of keys or triangles");
  for (int i = 0; i < keyCount_; ++i) {
    double* c = rest_.data() + (static_cast<size_t>(i) * 5 + 4) * t;  // the layout restOf() reads
    for (int k = 0; k < t; ++k) c[k] = kappa(k) * (0.5 * edgeMatrix(keys[i], triangles_[k]).determinant());
  }
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

namespace {

// Triangles per chunk of the local step: its edge matrices and gradient blocks, 8 arrays of this
// length (16 KB), stay in the core's L1 cache between the passes over the keys.
constexpr int kChunk = 256;

}  // namespace

double DeformationEnergy::evaluate(const Eigen::MatrixX2d& x, const ActiveKeys& keys, Eigen::MatrixX2d& gradient,
                                   const RowSplit& vertices, const RowSplit& triangles) const {
  const int t = triangleCount(), n = static_cast<int>(x.rows());
  if (vertices.size() != n || triangles.size() != t || vertices.threads() != triangles.threads())
    throw std::invalid_argument("deformation energy: the thread split does not match the mesh");
  const int active = static_cast<int>(keys.index.size());
  const double* px = x.col(0).data();
  const double* py = x.col(1).data();
  double* gx = gradient.col(0).data();
  double* gy = gradient.col(1).data();
  const int* c0 = corner_[0].data();
  const int* c1 = corner_[1].data();
  const int* c2 = corner_[2].data();
  // Each block of triangles sums its own energy; the sums are added in block order afterwards, so
  // the energy is bit-identical from run to run (an OpenMP reduction adds them in arrival order).
  const int blocks = vertices.threads();
  std::vector<double> partial(static_cast<size_t>(blocks), 0.0);
  deferred_.resize(static_cast<size_t>(blocks));
#pragma omp parallel num_threads(blocks)
  {
    // The team may have fewer threads than blocks.
    const int self = omp_get_thread_num(), team = omp_get_num_threads();
    alignas(64) double D00[kChunk], D01[kChunk], D10[kChunk], D11[kChunk];
    alignas(64) double G00[kChunk], G01[kChunk], G10[kChunk], G11[kChunk];
    for (int p = self; p < blocks; p += team) {
      double energy = 0;
      const int ownBegin = vertices.begin(p), ownEnd = vertices.end(p);
      std::vector<DeferredGradient>& deferred = deferred_[p];
      deferred.clear();
      // dW/dx_v of corner vertex v: straight into the gradient if the block owns v, else kept
      // for v's owner to add after the barrier.
      const auto add = [&](int v, double ax, double ay) {
        if (v >= ownBegin && v < ownEnd) {
          gx[v] += ax;
          gy[v] += ay;
        } else {
          deferred.push_back({v, ax, ay});
        }
      };
      for (int first = triangles.begin(p); first < triangles.end(p); first += kChunk) {
        const int count = std::min(kChunk, triangles.end(p) - first);
        const int* k0 = c0 + first;
        const int* k1 = c1 + first;
        const int* k2 = c2 + first;
#pragma omp simd
        for (int j = 0; j < count; ++j) {
          D00[j] = px[k1[j]] - px[k0[j]];
          D01[j] = px[k2[j]] - px[k0[j]];
          D10[j] = py[k1[j]] - py[k0[j]];
          D11[j] = py[k2[j]] - py[k0[j]];
          G00[j] = G01[j] = G10[j] = G11[j] = 0.0;
        }
        for (int a = 0; a < active; ++a) {
          const double* r = restOf(keys.index[a]) + first;  // B00 B10 B01 B11 c
          const double* b00 = r;
          const double* b10 = r + t;
          const double* b01 = r + 2 * t;
          const double* b11 = r + 3 * t;
          const double* cw = r + 4 * t;
          const double w = keys.weight[a];
#pragma omp simd reduction(+ : energy)
          for (int j = 0; j < count; ++j) {
            // F = D B, R its closest rotation, G += 2 w c (F - R) B^T.
            const double f00 = D00[j] * b00[j] + D01[j] * b10[j], f01 = D00[j] * b01[j] + D01[j] * b11[j];
            const double f10 = D10[j] * b00[j] + D11[j] * b10[j], f11 = D10[j] * b01[j] + D11[j] * b11[j];
            double c, s;
            closestRotation(f00, f01, f10, f11, c, s);
            const double e00 = f00 - c, e01 = f01 + s, e10 = f10 - s, e11 = f11 - c;  // F - R
            const double weight = w * cw[j];
            energy += weight * (e00 * e00 + e01 * e01 + e10 * e10 + e11 * e11);
            const double two = 2.0 * weight;
            G00[j] += two * (e00 * b00[j] + e01 * b01[j]);
            G01[j] += two * (e00 * b10[j] + e01 * b11[j]);
            G10[j] += two * (e10 * b00[j] + e11 * b01[j]);
            G11[j] += two * (e10 * b10[j] + e11 * b11[j]);
          }
        }
        // Corner 0 receives -(G e_0 + G e_1), corners 1 and 2 the columns of G.
        for (int j = 0; j < count; ++j) {
          add(k0[j], -(G00[j] + G01[j]), -(G10[j] + G11[j]));
          add(k1[j], G00[j], G10[j]);
          add(k2[j], G01[j], G11[j]);
        }
      }
      partial[p] = energy;
    }
#pragma omp barrier
    // Each block adds what the other blocks' triangles left for its vertices, in block order.
    for (int p = self; p < blocks; p += team)
      for (int q = 0; q < blocks; ++q)
        for (const DeferredGradient& d : deferred_[q])
          if (d.vertex >= vertices.begin(p) && d.vertex < vertices.end(p)) {
            gx[d.vertex] += d.x;
            gy[d.vertex] += d.y;
          }
  }
  double energy = 0;
  for (double p : partial) energy += p;
  return energy;
}

}  // namespace ib
