#include "meshing/untangle.h"

#include "core/thread_budget.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <omp.h>
#include <tuple>

namespace ib {

namespace {

// The energy of one eps, over the free coordinates of all vertices (2n vector, x then y per vertex).
class WinslowEnergy {
 public:
  WinslowEnergy(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& rest, double scale, double theta)
      : triangles_(triangles), theta_(theta) {
    inverse_.resize(triangles.size());
    weight_.resize(triangles.size());
    double total = 0;
    for (size_t t = 0; t < triangles.size(); ++t) {
      const auto& tri = triangles[t];
      Eigen::Matrix2d r;
      r.col(0) = (rest.row(tri[1]) - rest.row(tri[0])).transpose() * scale;
      r.col(1) = (rest.row(tri[2]) - rest.row(tri[0])).transpose() * scale;
      inverse_[t] = r.inverse();
      weight_[t] = 0.5 * r.determinant();
      total += weight_[t];
    }
    for (double& w : weight_) w /= total;
  }

  void setEps(double eps) { eps_ = eps; }

  double chi(double d) const { return 0.5 * (d + std::sqrt(eps_ * eps_ + d * d)); }

  // Energy and its gradient at x (2n); also the smallest det J. Triangles in parallel (each writes
  // its own corner gradients), then a serial gather into the vertices.
  double evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& gradient, double& minDet) const {
    const int count = static_cast<int>(triangles_.size());
    cornerGradient_.resize(count);
    triangleEnergy_.resize(count);
    double lowest = std::numeric_limits<double>::infinity();
    const int team = count > 4000 ? budget_.threads() : 1;
#pragma omp parallel for num_threads(team) reduction(min : lowest) schedule(static)
    for (int t = 0; t < count; ++t) {
      const auto& tri = triangles_[t];
      const Eigen::Vector2d p0(x[2 * tri[0]], x[2 * tri[0] + 1]);
      Eigen::Matrix2d e;
      e.col(0) = Eigen::Vector2d(x[2 * tri[1]], x[2 * tri[1] + 1]) - p0;
      e.col(1) = Eigen::Vector2d(x[2 * tri[2]], x[2 * tri[2] + 1]) - p0;
      const Eigen::Matrix2d j = e * inverse_[t];
      const double d = j.determinant();
      lowest = std::min(lowest, d);
      const double root = std::sqrt(eps_ * eps_ + d * d);
      const double c = 0.5 * (d + root), dc = 0.5 * (1 + d / root);
      const double f = j.squaredNorm() / c, g = (d * d + 1) / c;
      triangleEnergy_[t] = weight_[t] * ((1 - theta_) * f + theta_ * g);
      Eigen::Matrix2d cof;  // d(det J) / dJ
      cof << j(1, 1), -j(1, 0), -j(0, 1), j(0, 0);
      const Eigen::Matrix2d dj =
          weight_[t] * ((1 - theta_) * (2 / c * j - f * dc / c * cof) + theta_ * (2 * d / c - g * dc / c) * cof);
      cornerGradient_[t] = dj * inverse_[t].transpose();  // columns: d energy / d corner 1, corner 2
    }
    // Serial sums: bit-identical from run to run (a reduction adds in thread arrival order).
    double energy = 0;
    for (double e : triangleEnergy_) energy += e;
    gradient.setZero(x.size());
    for (int t = 0; t < count; ++t) {
      const auto& tri = triangles_[t];
      const Eigen::Matrix2d& de = cornerGradient_[t];
      for (int a = 0; a < 2; ++a) {
        gradient[2 * tri[1] + a] += de(a, 0);
        gradient[2 * tri[2] + a] += de(a, 1);
        gradient[2 * tri[0] + a] -= de(a, 0) + de(a, 1);
      }
    }
    minDet = lowest;
    return energy;
  }

 private:
  const std::vector<Triangle>& triangles_;
  double theta_;
  double eps_ = 1e-10;
  std::vector<Eigen::Matrix2d> inverse_;  // per triangle: (scaled rest edge matrix)^-1, 2 x 2
  std::vector<double> weight_;            // per triangle: rest area over total rest area
  mutable std::vector<Eigen::Matrix2d> cornerGradient_;  // per triangle: scratch of evaluate(), 2 x 2
  mutable std::vector<double> triangleEnergy_;           // per triangle: scratch of evaluate()
  // The threads of the triangle loop (all cores, fewer while other programs need some): each
  // triangle writes its own entries, so the result does not depend on them.
  mutable ThreadBudget budget_{omp_get_max_threads()};
};

// L-BFGS with a backtracking Armijo line search; free coordinates only (mask 1 = free).
int minimize(const WinslowEnergy& energy, Eigen::VectorXd& x, const Eigen::VectorXd& mask, int iterations,
             int memory, double& value, double& minDet) {
  Eigen::VectorXd g, gNew, xNew;
  value = energy.evaluate(x, g, minDet);
  g = g.cwiseProduct(mask);
  std::deque<Eigen::VectorXd> s, y;
  std::deque<double> rho;
  int it = 0;
  for (; it < iterations; ++it) {
    if (g.lpNorm<Eigen::Infinity>() < 1e-12) break;
    // Two-loop recursion: direction = -H g.
    Eigen::VectorXd q = g;
    std::vector<double> alpha(s.size());
    for (int i = static_cast<int>(s.size()) - 1; i >= 0; --i) {
      alpha[i] = rho[i] * s[i].dot(q);
      q -= alpha[i] * y[i];
    }
    if (!s.empty()) q *= s.back().dot(y.back()) / y.back().squaredNorm();
    else q /= std::max(g.norm(), 1e-12) * 10;  // first step: a small move along -g
    for (size_t i = 0; i < s.size(); ++i) q += s[i] * (alpha[i] - rho[i] * y[i].dot(q));
    Eigen::VectorXd direction = -q;
    double slope = direction.dot(g);
    if (slope >= 0) {  // not a descent direction: restart from the gradient
      s.clear(), y.clear(), rho.clear();
      direction = -g / std::max(g.norm(), 1e-12);
      slope = direction.dot(g);
    }
    double step = 1, newValue = 0, newMinDet = 0;
    bool accepted = false;
    for (int k = 0; k < 40; ++k, step *= 0.5) {
      xNew = x + step * direction;
      newValue = energy.evaluate(xNew, gNew, newMinDet);
      if (std::isfinite(newValue) && newValue <= value + 1e-4 * step * slope) {
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
    gNew = gNew.cwiseProduct(mask);
    const Eigen::VectorXd sk = xNew - x, yk = gNew - g;
    const double sy = sk.dot(yk);
    const double decrease = value - newValue;
    x = xNew, g = gNew, minDet = newMinDet;
    value = newValue;
    if (sy > 1e-16) {
      s.push_back(sk), y.push_back(yk), rho.push_back(1 / sy);
      if (static_cast<int>(s.size()) > memory) s.pop_front(), y.pop_front(), rho.pop_front();
    }
    if (decrease <= 1e-7 * std::abs(value)) break;  // enough for one eps; the outer loop refines
  }
  return it;
}

}  // namespace

std::pair<double, int> smallestTriangleArea(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& positions) {
  double best = std::numeric_limits<double>::infinity();
  int worst = -1;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    const double a = signedArea(positions.row(tri[0]), positions.row(tri[1]), positions.row(tri[2]));
    if (a < best) best = a, worst = static_cast<int>(t);
  }
  return {best, worst};
}

UntangleResult untangle(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& rest,
                        Eigen::MatrixX2d& positions, const std::vector<char>& locked,
                        const UntangleOptions& options) {
  UntangleResult result;
  double restArea = 0, targetArea = 0;
  for (const auto& tri : triangles) {
    restArea += signedArea(rest.row(tri[0]), rest.row(tri[1]), rest.row(tri[2]));
    targetArea += signedArea(positions.row(tri[0]), positions.row(tri[1]), positions.row(tri[2]));
  }
  std::tie(result.minArea, result.worstTriangle) = smallestTriangleArea(triangles, positions);
  if (!(restArea > 0) || !(targetArea > 0)) return result;
  // Work in units where the target's total area is 1, so eps and det J are O(1).
  const double unit = std::sqrt(targetArea);
  WinslowEnergy energy(triangles, rest, std::sqrt(targetArea / restArea) / unit, options.theta);
  const int n = static_cast<int>(positions.rows());
  Eigen::VectorXd x(2 * n), mask(2 * n);
  for (int v = 0; v < n; ++v) {
    x[2 * v] = positions(v, 0) / unit, x[2 * v + 1] = positions(v, 1) / unit;
    mask[2 * v] = mask[2 * v + 1] = locked[v] ? 0.0 : 1.0;
  }
  Eigen::VectorXd gradient;
  double minDet = 0;
  double value = energy.evaluate(x, gradient, minDet);
  energy.setEps(std::sqrt(1e-12 + 0.04 * std::pow(std::min(minDet, 0.0), 2)));
  value = energy.evaluate(x, gradient, minDet);
  for (int outer = 0; outer < options.outerIterations; ++outer) {
    const double previous = value;
    result.innerIterations += minimize(energy, x, mask, options.innerIterations, options.memory, value, minDet);
    result.outerIterations = outer + 1;
    // The paper's eps update (section 3): shrink eps as fast as the energy decrease allows.
    const double sigma = std::max(1 - value / previous, 0.1);
    const double mu = (1 - sigma) * energy.chi(minDet);
    energy.setEps(minDet < mu ? 2 * std::sqrt(mu * (mu - minDet)) : 1e-10);
    value = energy.evaluate(x, gradient, minDet);
    if (options.progress) options.progress(outer + 1, options.outerIterations);
    if (minDet > 0 && std::abs(previous - value) <= options.energyTolerance * std::abs(value)) break;
  }
  for (int v = 0; v < n; ++v)
    if (!locked[v]) positions(v, 0) = x[2 * v] * unit, positions(v, 1) = x[2 * v + 1] * unit;
  std::tie(result.minArea, result.worstTriangle) = smallestTriangleArea(triangles, positions);
  result.injective = result.minArea > 0;
  return result;
}

bool harmonicFill(const std::vector<Triangle>& triangles, const std::vector<char>& fixed, Eigen::MatrixX2d& x) {
  const int n = static_cast<int>(x.rows());
  std::vector<int> unknown(n, -1);
  int count = 0;
  for (int v = 0; v < n; ++v)
    if (!fixed[v]) unknown[v] = count++;
  if (count == 0) return true;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(count, 2);
  for (const Triangle& t : triangles)
    for (int c = 0; c < 3; ++c)
      for (int d = 1; d < 3; ++d) {  // each triangle contributes each directed edge once per side
        const int v = t[c], w = t[(c + d) % 3];
        if (unknown[v] < 0) continue;
        entries.emplace_back(unknown[v], unknown[v], 1.0);
        if (unknown[w] >= 0) entries.emplace_back(unknown[v], unknown[w], -1.0);
        else rhs.row(unknown[v]) += x.row(w);
      }
  Eigen::SparseMatrix<double> laplacian(count, count);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::MatrixX2d filled = solver.solve(rhs);
  for (int v = 0; v < n; ++v)
    if (unknown[v] >= 0) x.row(v) = filled.row(unknown[v]);
  return true;
}

namespace {

// The uniform-weight harmonic extension of the moves of the `carried` vertices (a move per
// vertex, rows of `move`) to the other free ones, the locked ones fixed: n x 2, px. Where it
// cannot be solved, the carried moves alone.
Eigen::MatrixX2d harmonicSpread(const std::vector<Triangle>& triangles, const std::vector<char>& locked,
                                const std::vector<char>& carried, const Eigen::MatrixX2d& move) {
  std::vector<char> fixed(locked.size());
  for (size_t v = 0; v < fixed.size(); ++v) fixed[v] = locked[v] || carried[v];
  Eigen::MatrixX2d out = move;
  if (!harmonicFill(triangles, fixed, out)) return move;
  return out;
}

}  // namespace

UntangleResult untangleToPins(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& rest,
                              Eigen::MatrixX2d& positions, const std::vector<char>& locked, const std::vector<int>& pins,
                              const std::vector<Eigen::Vector2d>& targets, const UntangleOptions& options) {
  const int n = static_cast<int>(positions.rows());
  std::vector<char> held = locked;  // the boundary and the pins
  for (int v : pins) held[v] = 1;
  Eigen::MatrixX2d from(pins.size(), 2), move(pins.size(), 2);  // px: where the pins start, and their whole move
  for (size_t p = 0; p < pins.size(); ++p) {
    from.row(p) = positions.row(pins[p]);
    move.row(p) = targets[p].transpose() - from.row(p);
  }
  // Each step needs only a fold-free map to start the next one from (a failing step then costs a
  // sixth of a full untangling); the last map is polished with the full options.
  UntangleOptions stepOptions = options;
  stepOptions.outerIterations = std::min(options.outerIterations, 10);
  stepOptions.progress = nullptr;
  UntangleResult result;
  double done = 0, step = 1;  // fractions of the whole move
  while (done < 1) {
    const double to = std::min(1.0, done + step);
    // Every free vertex within half the pin's distance to the boundary moves with the pin, as a
    // disc; the rest follow harmonically. A disc's move spreads over the ring between it and the
    // boundary, so a step may be a good part of that distance (a lone vertex would fold its
    // neighbours once it moves by more than about an edge).
    std::vector<char> carried(n, 0);
    Eigen::MatrixX2d stepMove = Eigen::MatrixX2d::Zero(n, 2);
    std::vector<double> radius(pins.size(), std::numeric_limits<double>::infinity());
    for (size_t p = 0; p < pins.size(); ++p)
      for (int v = 0; v < n; ++v)
        if (locked[v]) radius[p] = std::min(radius[p], 0.5 * (positions.row(v) - positions.row(pins[p])).norm());
    for (int v = 0; v < n; ++v) {
      if (locked[v]) continue;
      int nearest = -1;
      double best = std::numeric_limits<double>::infinity();
      for (size_t p = 0; p < pins.size(); ++p) {
        const double d = (positions.row(v) - positions.row(pins[p])).norm();
        if (d <= radius[p] && d < best) best = d, nearest = static_cast<int>(p);
      }
      if (nearest < 0) continue;
      carried[v] = 1;
      stepMove.row(v) = (to - done) * move.row(nearest);
    }
    Eigen::MatrixX2d candidate = positions + harmonicSpread(triangles, locked, carried, stepMove);
    for (size_t p = 0; p < pins.size(); ++p)
      candidate.row(pins[p]) = to >= 1 ? targets[p].transpose() : Eigen::RowVector2d(from.row(p) + to * move.row(p));
    result = untangle(triangles, rest, candidate, held, stepOptions);
    if (result.injective) {
      positions = candidate;
      done = to;
      step = std::min(1.0, 2 * step);
    } else if ((step /= 2) < 1.0 / 128) {
      return result;
    }
  }
  Eigen::MatrixX2d polished = positions;
  const UntangleResult last = untangle(triangles, rest, polished, held, options);
  if (last.injective) positions = polished, result = last;
  return result;
}

}  // namespace ib
