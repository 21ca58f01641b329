// The objective of Comesh Optimization (paper section 4, eq. 8) and its two parts, with gradients.
// Positions are n x 2 (any length unit); triangles are positive in every key they are evaluated on.
// odtEnergy and mipsEnergy are the plain per-triangle forms with their gradients; the optimizer
// runs on faster forms of the same sums (comeshEnergy's one pass per key, and BlockEnergy in
// comesh_block_energy.h), which the tests check against these.
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

// ODT energy of one key (eq. 4) in its exact form: the integral over the mesh of the linear
// interpolant of |x|^2 minus |x|^2, which per triangle is a_t / 12 * (sum of squared edge
// lengths) (Chen and Xu 2004). Units: length^4. Adds d/dX to `gradient` (n x 2) when given.
// (The paper writes 1/4 sum_j |X^j|^2 Gamma_j - q; the interpolation error has 1/3 there, and q
// is the integral of |x|^2, which we keep so that sliding boundary vertices see it too.)
double odtEnergy(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& x, Eigen::MatrixX2d* gradient);

// MIPS distortion of the map from key i to key j (eq. 5): sum_t a_t(X_i) (s1/s2 + s2/s1), s the
// singular values of the map's 2 x 2 Jacobian; per triangle |X_j-edges * adj(X_i-edges)|^2 / (4 a_t(X_j)).
// Units: length^2. Infinite when a triangle is not positive in X_j. Adds gradients when given.
double mipsEnergy(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& xi, const Eigen::MatrixX2d& xj,
                  Eigen::MatrixX2d* gradientI, Eigen::MatrixX2d* gradientJ);

// Total signed area of a key.
double totalArea(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& x);

// The objective of eq. 8: sum over keys of ODT(X_i) / area(X_i), plus the cyclic MIPS sum (eq. 6)
// MIPS(X_i, X_[i+1]) over i (for two keys: both directions; for one key: none). Units: length^2.
// `odtWeights[i]` scales key i's ODT term (empty: all 1, eq. 8 as printed).
double comeshEnergy(const std::vector<Triangle>& triangles, const std::vector<Eigen::MatrixX2d>& keys,
                    const std::vector<double>& odtWeights = {});

}  // namespace ib
