// W_D, the triangle ARAP energy of eq. (16), summed over keys with interpolation weights. In the
// paper's form (ShapeMetric::kPerKey):
//   sum_i w_i sum_t kappa_t a_t(X_i) || F_t(X_i, x) - R_ti ||_F^2,   F = D(x) B_ti,
// where D(x) = [x1 - x0, x2 - x0] (2x2, edge vectors as columns), B_ti = D(X_i)^{-1} and R_ti
// the rotation closest to F (the local step). Written with the key's metric M_ti = c_ti B_ti B_ti^T
// (c_ti = kappa_t a_t(X_i)), key i's term is tr((D - R_ti D_ti) M_ti (D - R_ti D_ti)^T). The
// shared form (ShapeMetric::kShared, shape_metric.h) puts M_t(w) = sum_j w_j M_tj in every key's
// term, and R_ti is then the rotation closest to D M_t(w) D_ti^T. All positions are n x 2, one row
// per vertex.
#pragma once

#include "core/thread_block.h"
#include "interpolation/shape_metric.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <vector>

namespace ib {

// Weights restricted to the keys that take part: w_i > 0. Keys with zero weight cost nothing.
struct ActiveKeys {
  std::vector<int> index;      // key indices i with w_i > 0
  std::vector<double> weight;  // their w_i
};
ActiveKeys activeKeys(const Eigen::VectorXd& w);

class DeformationEnergy {
 public:
  // keys: X_i (n x 2 each); kappa: t x 1. Rest triangles must have positive area.
  DeformationEnergy(const std::vector<Triangle>& triangles, const std::vector<Eigen::MatrixX2d>& keys,
                    const Eigen::VectorXd& kappa);

  // New stiffness kappa (t x 1) with the same keys X_i as the constructor's: c_ti = kappa_t
  // a_t(X_i), exactly as the constructor computes them.
  void setStiffness(const std::vector<Eigen::MatrixX2d>& keys, const Eigen::VectorXd& kappa);

  int triangleCount() const { return static_cast<int>(triangles_.size()); }
  const std::vector<Triangle>& triangles() const { return triangles_; }

  // Triangle k's 2x2 metric M_k(w) = 2 sum_i w_i c_ki B_ki B_ki^T, so that with rotations frozen
  // the Hessian of W_D for one coordinate is sum_t E^T M_t E (E maps corner values to edges).
  Eigen::Matrix2d metric(int k, const ActiveKeys& keys) const;

  // Local step fused with evaluation: rotations for every triangle and active key, returns W_D
  // and adds dW_D/dx (n x 2) to gradient. Thread p takes the triangles [triangles.begin(p),
  // triangles.end(p)) and sums the gradient of the vertices [vertices.begin(p), vertices.end(p))
  // (both splits with the same thread count; std::invalid_argument if they do not match the
  // mesh). Uses internal buffers: one evaluate() at a time per object.
  double evaluate(const Eigen::MatrixX2d& x, const ActiveKeys& keys, Eigen::MatrixX2d& gradient,
                  const RowSplit& vertices, const RowSplit& triangles, ShapeMetric shape = ShapeMetric::kPerKey) const;

 private:
  std::vector<Triangle> triangles_;
  int keyCount_ = 0;
  // Per key i, five arrays over triangles (structure of arrays, so the local step vectorizes):
  // B_ti = D(X_i)^{-1} entries b00, b10, b01, b11, then c_ti = kappa_t * area_ti.
  std::vector<double> rest_;                  // m x 5 x t
  const double* restOf(int key) const { return rest_.data() + static_cast<size_t>(key) * 5 * triangles_.size(); }
  std::array<std::vector<int>, 3> corner_;    // vertex of each corner, per triangle
  // Gradient a block's triangles owe a vertex another block owns, added by that block after a
  // barrier: one list per block, reused from call to call.
  struct DeferredGradient {
    int vertex;
    double x, y;
  };
  mutable std::vector<std::vector<DeferredGradient>> deferred_;
};

// Cosine and sine of the rotation closest to F = [f00 f01; f10 f11] in the Frobenius norm (2D
// polar decomposition, valid for any F): it maximizes tr(R^T F) = c (f00 + f11) + s (f10 - f01).
// Branch-free, so the local step vectorizes across triangles; the identity for F with no
// rotational part.
inline void closestRotation(double f00, double f01, double f10, double f11, double& c, double& s) {
  const double sc = f00 + f11, sn = f10 - f01, norm2 = sc * sc + sn * sn;
  const bool ok = norm2 > 1e-300;
  const double inverse = 1.0 / std::sqrt(ok ? norm2 : 1.0);
  c = ok ? sc * inverse : 1.0;
  s = ok ? sn * inverse : 0.0;
}

// The same as a matrix.
Eigen::Matrix2d closestRotation(const Eigen::Matrix2d& F);

}  // namespace ib
