#include "interpolation/gap_pull.h"

#include <Eigen/LU>
#include <map>
#include <stdexcept>
#include <tuple>

namespace ib {

namespace {

Eigen::Matrix2d edges(const Eigen::MatrixX2d& x, const Triangle& t) {
  Eigen::Matrix2d d;
  d.col(0) = (x.row(t[1]) - x.row(t[0])).transpose();
  d.col(1) = (x.row(t[2]) - x.row(t[0])).transpose();
  return d;
}


// gamma of a pull's key: how firmly its rotation keeps to the frozen one, kappa o^2 (|U|^2 + |V|^2),
// the size of the pull's own term once the gap is open.
double anchorOf(double open, const Eigen::Vector2d& U, const Eigen::Vector2d& V) {
  constexpr double kAnchor = 0.1;  // kappa
  return kAnchor * open * open * (U.squaredNorm() + V.squaredNorm());
}

// The rotation minimizing Q(u - o R U, v - o R V) + gamma |R - Rb|_F^2: closest to
// o ((u + v/2) U^T + (v + u/2) V^T) + gamma Rb.
Eigen::Matrix2d pullRotation(const Eigen::Vector2d& u, const Eigen::Vector2d& v, double open, const Eigen::Vector2d& U,
                             const Eigen::Vector2d& V, const Eigen::Matrix2d& Rb, double gamma) {
  const Eigen::Matrix2d S = open * ((u + 0.5 * v) * U.transpose() + (v + 0.5 * u) * V.transpose()) + gamma * Rb;
  return closestRotation(S);
}

}  // namespace

GapPull::GapPull(const Multimesh& mesh, const std::vector<Eigen::MatrixX2d>& keys, const CohesiveEnergy& cohesive,
                 const CohesiveParams& params)
    : params_(params) {
  std::vector<int> triangleAt(mesh.vertexCount(), -1);
  for (size_t t = 0; t < mesh.triangles().size(); ++t)
    for (int v : mesh.triangles()[t])
      if (triangleAt[v] < 0) triangleAt[v] = static_cast<int>(t);
  // The keys that close each distinct pair, and its first term.
  std::map<std::tuple<int, int, int, int>, std::pair<std::vector<char>, int>> closed;
  const auto& terms = cohesive.terms();
  for (size_t j = 0; j < terms.size(); ++j) {
    const CohesivePair& p = terms[j].pair;
    auto& entry = closed[{p.a, p.b, p.c, p.d}];
    if (entry.first.empty()) entry = {std::vector<char>(mesh.keyCount(), 0), static_cast<int>(j)};
    entry.first[terms[j].key] = 1;
  }
  for (const auto& [id, entry] : closed) {
    const CohesiveTerm& term = terms[entry.second];
    Pull pull;
    pull.pair = term.pair;
    pull.restLength = term.restLength;
    if (triangleAt[pull.pair.a] < 0 || triangleAt[pull.pair.c] < 0)
      throw std::invalid_argument("gap pull: a cohesive pair's vertex is in no triangle");
    pull.at = mesh.triangles()[triangleAt[pull.pair.a]];
    pull.ac = mesh.triangles()[triangleAt[pull.pair.c]];
    for (int k = 0; k < mesh.keyCount(); ++k) {
      if (entry.first[k]) continue;
      const Eigen::MatrixX2d& X = keys[k];
      pull.key.push_back(k);
      pull.U.push_back((X.row(pull.pair.a) - X.row(pull.pair.c)).transpose());
      pull.V.push_back((X.row(pull.pair.b) - X.row(pull.pair.d)).transpose());
      pull.Ma.push_back(edges(X, pull.at).inverse());
      pull.Mc.push_back(edges(X, pull.ac).inverse());
      pull.R.push_back(Eigen::Matrix2d::Identity());
    }
    if (!pull.key.empty()) pulls_.push_back(std::move(pull));
  }
}

double GapPull::share(const Pull& pull, const Eigen::VectorXd& w) const {
  if (params_.timing == CutTiming::kTau) return 0;
  double open = 0;
  for (int k : pull.key) open += w(k);
  if (open <= 0 || open >= 1) return 0;  // no closing pull to part from, or nothing left of it
  return (1 - releaseRamp(open, params_)) * pullFade(open, params_) / open;  // per unit of an open key's weight
}

double GapPull::springConstant(int p, const Eigen::VectorXd& w) const {
  const Pull& pull = pulls_[p];
  const double s = share(pull, w);
  if (s <= 0) return 0;
  double weight = 0;
  for (int k : pull.key) weight += w(k);
  return s * weight * pull.restLength / 3.0 * params_.lambda;  // (1 - r) l/3 lambda
}

double GapPull::strength(int p, const Eigen::VectorXd& w) const {
  const Pull& pull = pulls_[p];
  double weight = 0;
  for (int k : pull.key) weight += w(k);
  return std::max(0.0, share(pull, w)) * weight;
}

void GapPull::freezeRotations(const Eigen::MatrixX2d& x) {
  for (Pull& pull : pulls_) {
    const Eigen::Matrix2d Da = edges(x, pull.at), Dc = edges(x, pull.ac);
    for (size_t i = 0; i < pull.key.size(); ++i) pull.R[i] = closestRotation(Eigen::Matrix2d(Da * pull.Ma[i] + Dc * pull.Mc[i]));
  }
}

double GapPull::evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, Eigen::MatrixX2d& gradient) const {
  double energy = 0;
  for (const Pull& pull : pulls_) {
    const double pullShare = share(pull, w);
    if (pullShare <= 0) continue;
    const CohesivePair& p = pull.pair;
    const Eigen::Vector2d u = (x.row(p.a) - x.row(p.c)).transpose();
    const Eigen::Vector2d v = (x.row(p.b) - x.row(p.d)).transpose();
    const double scale = pull.restLength / 3.0 * params_.lambda;
    double open = 0;
    for (int k : pull.key) open += w(k);
    for (size_t i = 0; i < pull.key.size(); ++i) {
      const double weight = pullShare * w(pull.key[i]);
      if (weight <= 0) continue;
      const double gamma = anchorOf(open, pull.U[i], pull.V[i]);
      const Eigen::Matrix2d R = pullRotation(u, v, open, pull.U[i], pull.V[i], pull.R[i], gamma);
      const Eigen::Vector2d du = u - open * R * pull.U[i], dv = v - open * R * pull.V[i];
      energy += weight * scale * (du.squaredNorm() + du.dot(dv) + dv.squaredNorm() + gamma * (R - pull.R[i]).squaredNorm());
      const Eigen::Vector2d gu = weight * scale * (2.0 * du + dv), gv = weight * scale * (du + 2.0 * dv);
      gradient.row(p.a) += gu.transpose();
      gradient.row(p.c) -= gu.transpose();
      gradient.row(p.b) += gv.transpose();
      gradient.row(p.d) -= gv.transpose();
    }
  }
  return energy;
}

}  // namespace ib

