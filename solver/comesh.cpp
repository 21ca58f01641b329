#include "comesh.h"

#include "comesh_energy.h"

#include <Eigen/Dense>
#include <chrono>
#include <cmath>

namespace ib {

namespace {

class VertexStepper {
 public:
  VertexStepper(const std::vector<Triangle>& triangles, int vertexCount, const std::vector<char>& movable)
      : triangles_(triangles), movable_(movable), around_(vertexCount) {
    for (size_t t = 0; t < triangles.size(); ++t)
      for (int v : triangles[t]) around_[v].push_back(static_cast<int>(t));
  }

  // One projected gradient step on key i (paper: gradient_descent_step). Returns the relative
  // energy decrease (0 when no step lowered the energy).
  double step(std::vector<Eigen::MatrixX2d>& keys, int i, double& stepSize) const {
    Eigen::MatrixX2d gradient;
    const double before = comeshBlockEnergy(triangles_, keys, i, &gradient);
    for (int v = 0; v < gradient.rows(); ++v)
      if (!movable_[v]) gradient.row(v).setZero();
    const double largest = gradient.rowwise().norm().maxCoeff();
    if (!(largest > 0)) return 0;
    const Eigen::MatrixX2d start = keys[i];
    if (!(stepSize > 0)) stepSize = 0.1 * meanEdge(start) / largest;
    for (int attempt = 0; attempt < 20; ++attempt) {
      moveVertices(keys[i], start, gradient, stepSize);
      const double after = comeshBlockEnergy(triangles_, keys, i, nullptr);
      if (after < before) {
        stepSize *= 1.5;
        return (before - after) / before;
      }
      stepSize *= 0.5;
    }
    keys[i] = start;
    return 0;
  }

 private:
  double meanEdge(const Eigen::MatrixX2d& x) const {
    double sum = 0;
    for (const Triangle& t : triangles_) sum += (x.row(t[1]) - x.row(t[0])).norm();
    return sum / std::max<size_t>(triangles_.size(), 1);
  }

  // x = start - stepSize * gradient, vertex by vertex, each step halved until its one-ring is positive.
  void moveVertices(Eigen::MatrixX2d& x, const Eigen::MatrixX2d& start, const Eigen::MatrixX2d& gradient,
                    double stepSize) const {
    x = start;
    for (int v = 0; v < x.rows(); ++v) {
      if (!movable_[v]) continue;
      Eigen::RowVector2d move = -stepSize * gradient.row(v);
      for (int halving = 0; halving < 30; ++halving, move *= 0.5) {
        x.row(v) = start.row(v) + move;
        if (oneRingPositive(x, v)) break;
        x.row(v) = start.row(v);
      }
    }
  }

  bool oneRingPositive(const Eigen::MatrixX2d& x, int v) const {
    for (int t : around_[v])
      if (!(edgeMatrix(x, triangles_[t]).determinant() > 0)) return false;
    return true;
  }

  const std::vector<Triangle>& triangles_;
  const std::vector<char>& movable_;
  std::vector<std::vector<int>> around_;  // per vertex: incident triangles
};

}  // namespace

std::vector<char> interiorVertices(const Multimesh& mesh) {
  std::vector<char> movable(mesh.vertexCount(), 0);
  for (auto v : mesh.topology().vertices()) movable[v.idx()] = !mesh.topology().is_boundary(v);
  return movable;
}

ComeshReport comeshOptimize(Multimesh& mesh, const std::vector<char>& movable, const ComeshOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const std::vector<Triangle> triangles = mesh.triangles();
  const int m = mesh.keyCount();
  std::vector<Eigen::MatrixX2d> keys;
  for (int k = 0; k < m; ++k) keys.push_back(mesh.keyPositions(k));
  const VertexStepper stepper(triangles, mesh.vertexCount(), movable);
  std::vector<double> stepSize(m, 0.0);
  ComeshReport report;
  for (int outer = 0; outer < options.outerIterations; ++outer) {
    report.outerIterations = outer + 1;
    double total = 0;
    for (int i = 0; i < m; ++i) {
      double innerResidual = 0;
      for (int inner = 0; inner < options.innerIterations; ++inner) {
        ++report.innerIterations;
        const double residual = stepper.step(keys, i, stepSize[i]);
        innerResidual = std::max(innerResidual, residual);
        if (residual < options.innerTolerance) break;
      }
      total += innerResidual;
    }
    if (total < options.outerTolerance) break;
  }
  for (int k = 0; k < m; ++k) mesh.setKeyPositions(k, keys[k]);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return report;
}

}  // namespace ib
