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

// One key's terms over a chunk of `count` triangles in the paper's form: F = D B, R its closest
// rotation, energy w c |F - R|^2, and G += 2 w c (F - R) B^T. r: the key's rest arrays at the
// chunk's first triangle (B00 B10 B01 B11 c, each `stride` apart). Returns the chunk's energy.
double perKeyTerms(const double* r, int stride, double w, int count, const double* D00, const double* D01,
                   const double* D10, const double* D11, double* G00, double* G01, double* G10, double* G11) {
  const double* b00 = r;
  const double* b10 = r + stride;
  const double* b01 = r + 2 * stride;
  const double* b11 = r + 3 * stride;
  const double* cw = r + 4 * stride;
  double energy = 0;
#pragma omp simd reduction(+ : energy)
  for (int j = 0; j < count; ++j) {
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
  return energy;
}

// The same in the shared metric M (M00, M01 = M10, M11 per triangle): K = D_i = B^-1 the key's
// edge matrix, R the rotation closest to D M K^T, E = D - R K, energy w tr(E M E^T) and
// G += 2 w E M.
double sharedTerms(const double* r, int stride, double w, int count, const double* D00, const double* D01,
                   const double* D10, const double* D11, const double* M00, const double* M01, const double* M11,
                   double* G00, double* G01, double* G10, double* G11) {
  const double* b00 = r;
  const double* b10 = r + stride;
  const double* b01 = r + 2 * stride;
  const double* b11 = r + 3 * stride;
  double energy = 0;
#pragma omp simd reduction(+ : energy)
  for (int j = 0; j < count; ++j) {
    const double inv = 1.0 / (b00[j] * b11[j] - b01[j] * b10[j]);
    const double k00 = b11[j] * inv, k01 = -b01[j] * inv, k10 = -b10[j] * inv, k11 = b00[j] * inv;
    const double m00 = M00[j], m01 = M01[j], m11 = M11[j];
    // P = D M K^T: first D M, then times K^T.
    const double q00 = D00[j] * m00 + D01[j] * m01, q01 = D00[j] * m01 + D01[j] * m11;
    const double q10 = D10[j] * m00 + D11[j] * m01, q11 = D10[j] * m01 + D11[j] * m11;
    const double p00 = q00 * k00 + q01 * k01, p01 = q00 * k10 + q01 * k11;
    const double p10 = q10 * k00 + q11 * k01, p11 = q10 * k10 + q11 * k11;
    double c, s;
    closestRotation(p00, p01, p10, p11, c, s);
    // E = D - R K, R = [c -s; s c].
    const double e00 = D00[j] - (c * k00 - s * k10), e01 = D01[j] - (c * k01 - s * k11);
    const double e10 = D10[j] - (s * k00 + c * k10), e11 = D11[j] - (s * k01 + c * k11);
    // E M, and tr(E M E^T) = sum of (E M) .* E.
    const double em00 = e00 * m00 + e01 * m01, em01 = e00 * m01 + e01 * m11;
    const double em10 = e10 * m00 + e11 * m01, em11 = e10 * m01 + e11 * m11;
    energy += w * (em00 * e00 + em01 * e01 + em10 * e10 + em11 * e11);
    const double two = 2.0 * w;
    G00[j] += two * em00;
    G01[j] += two * em01;
    G10[j] += two * em10;
    G11[j] += two * em11;
  }
  return energy;
}

}  // namespace

double DeformationEnergy::evaluate(const Eigen::MatrixX2d& x, const ActiveKeys& keys, Eigen::MatrixX2d& gradient,
                                   const RowSplit& vertices, const RowSplit& triangles, ShapeMetric shape) const {
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
#pragma omp parallel num_threads(teamFor(blocks))
  {
    // The team may have fewer threads than blocks.
    const int self = omp_get_thread_num(), team = omp_get_num_threads();
    alignas(64) double D00[kChunk], D01[kChunk], D10[kChunk], D11[kChunk];
    alignas(64) double G00[kChunk], G01[kChunk], G10[kChunk], G11[kChunk];
    alignas(64) double M00[kChunk], M01[kChunk], M11[kChunk];
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
        if (shape == ShapeMetric::kPerKey) {
          for (int a = 0; a < active; ++a)
            energy += perKeyTerms(restOf(keys.index[a]) + first, t, keys.weight[a], count, D00, D01, D10, D11, G00, G01, G10, G11);
        } else {
          // M(w) = sum_i w_i c_i B_i B_i^T, symmetric: M00, M01 (= M10), M11.
#pragma omp simd
          for (int j = 0; j < count; ++j) M00[j] = M01[j] = M11[j] = 0.0;
          for (int a = 0; a < active; ++a) {
            const double* r = restOf(keys.index[a]) + first;  // B00 B10 B01 B11 c
            const double w = keys.weight[a];
#pragma omp simd
            for (int j = 0; j < count; ++j) {
              const double b00 = r[j], b10 = r[t + j], b01 = r[2 * t + j], b11 = r[3 * t + j], wc = w * r[4 * t + j];
              M00[j] += wc * (b00 * b00 + b01 * b01);
              M01[j] += wc * (b00 * b10 + b01 * b11);
              M11[j] += wc * (b10 * b10 + b11 * b11);
            }
          }
          for (int a = 0; a < active; ++a)
            energy += sharedTerms(restOf(keys.index[a]) + first, t, keys.weight[a], count, D00, D01, D10, D11, M00, M01, M11,
                                  G00, G01, G10, G11);
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
