#include "animation/dynamics.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace ib {

namespace {

constexpr double kMaxBlend = 0.95;

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace

double dynamicsFade(const DynamicsParams& params, const Timeline::Position& position, int segmentCount) {
  if (position.segment < 0 || position.segment >= segmentCount || position.u == 0) return 0;
  return smoothstep((1 - position.u) / params.settle);
}

double dynamicsBlend(const DynamicsParams& params, const Timeline::Position& position, int segmentCount,
                     double deviation) {
  if (!params.enabled()) return 0;
  const double budget = params.epsilon * params.maxDeviation;
  const double pullBack = 1 / (1 + (deviation / budget) * (deviation / budget));
  return std::min(kMaxBlend, params.epsilon * dynamicsFade(params, position, segmentCount) * pullBack);
}

Eigen::VectorXd lumpedMasses(const Multimesh& mesh) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(mesh.vertexCount());
  const std::vector<Triangle> triangles = mesh.triangles();
  for (int k = 0; k < mesh.keyCount(); ++k) {
    const Eigen::MatrixX2d X = mesh.keyPositions(k);
    for (const Triangle& t : triangles) {
      const double third = std::abs(signedArea(X.row(t[0]), X.row(t[1]), X.row(t[2]))) / 3;
      for (int c = 0; c < 3; ++c) m(t[c]) += third;
    }
  }
  return m / m.sum();
}

Eigen::VectorXd anchorWeights(const Multimesh& mesh) {
  Eigen::VectorXd kappaArea = Eigen::VectorXd::Zero(mesh.vertexCount());
  Eigen::VectorXd area = Eigen::VectorXd::Zero(mesh.vertexCount());
  const std::vector<Triangle> triangles = mesh.triangles();
  const Eigen::MatrixX2d X = mesh.keyPositions(0);
  for (size_t t = 0; t < triangles.size(); ++t) {
    const double a = std::abs(signedArea(X.row(triangles[t][0]), X.row(triangles[t][1]), X.row(triangles[t][2])));
    for (int c = 0; c < 3; ++c) {
      kappaArea(triangles[t][c]) += mesh.stiffness(static_cast<int>(t)) * a;
      area(triangles[t][c]) += a;
    }
  }
  const Eigen::VectorXd kappa = kappaArea.cwiseQuotient(area.cwiseMax(1e-300));
  return kappa / kappa.maxCoeff();
}

Eigen::Vector2d externalAcceleration(const DynamicsParams& params, double time) {
  return params.gravity + params.wind * (1 + params.gust * std::sin(2 * M_PI * params.gustFrequency * time));
}

void validateDynamics(const DynamicsParams& p, const std::string& where) {
  const auto require = [&](bool ok, const std::string& field, const std::string& rule) {
    if (!ok) throw InputError(where + field + ": " + rule);
  };
  require(p.epsilon >= 0 && p.epsilon <= 1, "epsilon", "must be in [0, 1]");
  require(p.gravity.allFinite(), "gravity", "must be finite");
  require(p.wind.allFinite(), "wind", "must be finite");
  require(p.gust >= 0 && p.gust <= 1, "gust", "must be in [0, 1]");
  require(p.gustFrequency > 0 && std::isfinite(p.gustFrequency), "gust_frequency", "must be > 0");
  require(p.mu >= 0 && std::isfinite(p.mu), "mu", "must be >= 0");
  require(p.anchor > 0 && std::isfinite(p.anchor), "anchor", "must be > 0");
  require(p.settle > 0 && p.settle <= 1, "settle", "must be in (0, 1]");
  require(p.maxDeviation > 0 && std::isfinite(p.maxDeviation), "max_deviation", "must be > 0");
}

}  // namespace ib
