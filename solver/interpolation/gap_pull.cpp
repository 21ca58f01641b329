#include "interpolation/gap_pull.h"

#include "multimesh/cut_chains.h"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

namespace ib {

namespace {

Eigen::Matrix2d edges(const Eigen::MatrixX2d& x, const Triangle& t) {
  Eigen::Matrix2d d;
  d.col(0) = (x.row(t[1]) - x.row(t[0])).transpose();
  d.col(1) = (x.row(t[2]) - x.row(t[0])).transpose();
  return d;
}

// gamma of a pull's key: how firmly its rotation keeps to the anchor, kappa o^2 (|U|^2 + |V|^2),
// a hundredth of the pull's own term once the gap is open (docs/solver.md, "Cut timing": 0.1
// left growing-flower's and chinese-character's solves at the iteration cap on 19 frames).
double anchorOf(double open, const Eigen::Vector2d& U, const Eigen::Vector2d& V) {
  constexpr double kAnchor = 0.01;  // kappa
  return kAnchor * open * open * (U.squaredNorm() + V.squaredNorm());
}

}  // namespace

GapPull::GapPull(const Multimesh& mesh, const std::vector<Eigen::MatrixX2d>& keys, const CohesiveEnergy& cohesive,
                 const CohesiveParams& params)
    : params_(params) {
  std::vector<int> triangleAt(mesh.vertexCount(), -1);
  for (size_t t = 0; t < mesh.triangles().size(); ++t)
    for (int v : mesh.triangles()[t])
      if (triangleAt[v] < 0) triangleAt[v] = static_cast<int>(t);
  // The distinct pairs, the keys that close each and its cut (cut_chains.h), and its first term.
  const CutChains cuts = cutChains(mesh);
  const auto& terms = cohesive.terms();
  std::vector<int> firstTerm(cuts.pairs.size(), -1);
  for (size_t j = 0; j < terms.size(); ++j) {
    int& first = firstTerm[cuts.indexOf(terms[j].pair)];
    if (first < 0) first = static_cast<int>(j);
  }
  for (size_t id = 0; id < cuts.pairs.size(); ++id) {
    if (firstTerm[id] < 0) continue;
    const CohesiveTerm& term = terms[firstTerm[id]];
    Pull pull;
    pull.pair = term.pair;
    pull.term = firstTerm[id];
    pull.restLength = term.restLength;
    pull.chain = cuts.chainOf[id];
    if (triangleAt[pull.pair.a] < 0 || triangleAt[pull.pair.c] < 0)
      throw std::invalid_argument("gap pull: a cohesive pair's vertex is in no triangle");
    pull.at = mesh.triangles()[triangleAt[pull.pair.a]];
    pull.ac = mesh.triangles()[triangleAt[pull.pair.c]];
    for (int k = 0; k < mesh.keyCount(); ++k) {
      if (cuts.closedIn[id][k]) continue;
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
  chains_ = cuts.chains;
  for (const Pull& pull : pulls_) slots_ = std::max(slots_, pull.key.size());
}

double GapPull::share(const Pull& pull, const Eigen::VectorXd& w) const {
  if (params_.timing == CutTiming::kTau) return 0;
  double open = 0;
  for (int k : pull.key) open += w(k);
  if (open <= 0 || open >= 1) return 0;  // no closing pull to part from, or nothing left of it
  const CutRelease own = timingOf(pull.term, params_);
  return (1 - releaseRamp(open, own.release, own.window)) * pullFade(open, own.release, own.window) / open;  // per unit of an open key's weight
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

template <class Visit>
void GapPull::forEachTerm(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, Visit&& visit) const {
  for (const Pull& pull : pulls_) {
    const double pullShare = share(pull, w);
    if (pullShare <= 0) continue;
    const CohesivePair& p = pull.pair;
    const Eigen::Vector2d u = (x.row(p.a) - x.row(p.c)).transpose();
    const Eigen::Vector2d v = (x.row(p.b) - x.row(p.d)).transpose();
    double open = 0;
    for (int k : pull.key) open += w(k);
    const double scale = pull.restLength / 3.0 * params_.lambda;
    for (size_t i = 0; i < pull.key.size(); ++i) {
      const double k = pullShare * w(pull.key[i]) * scale;
      if (k > 0) visit(pull, i, u, v, open, k);
    }
  }
}

std::vector<Eigen::Matrix2d> GapPull::rotations(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, const GroupAngles& turn) const {
  // Per chain and open key (in the order of its pulls' key lists): the rotation minimizing the
  // chain's pulls, the closest to sum_p k_p [o ((u + v/2) U^T + (v + u/2) V^T) + gamma_p B_p].
  std::vector<Eigen::Matrix2d> S(static_cast<size_t>(chains_) * slots_, Eigen::Matrix2d::Zero());
  forEachTerm(x, w, [&](const Pull& pull, size_t i, const Eigen::Vector2d& u, const Eigen::Vector2d& v, double open, double k) {
    S[pull.chain * slots_ + i] += k * (open * ((u + 0.5 * v) * pull.U[i].transpose() + (v + 0.5 * u) * pull.V[i].transpose()) +
                                       anchorOf(open, pull.U[i], pull.V[i]) * turn.of(pull.pair.a) * pull.R[i]);
  });
  for (Eigen::Matrix2d& m : S) m = m.isZero(0) ? Eigen::Matrix2d::Identity() : closestRotation(m);
  return S;
}

Eigen::Matrix2d GroupAngles::of(int v) const {
  if (!groups || angle.empty()) return Eigen::Matrix2d::Identity();
  const double a = angle[static_cast<size_t>(groups->groupOf(v))];
  Eigen::Matrix2d r;
  r << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return r;
}

double GapPull::evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, Eigen::MatrixX2d& gradient,
                         const GroupAngles& angles, std::vector<double>* angleGradient) const {
  const std::vector<Eigen::Matrix2d> turn = rotations(x, w, angles);
  double energy = 0;
  forEachTerm(x, w, [&](const Pull& pull, size_t i, const Eigen::Vector2d& u, const Eigen::Vector2d& v, double open, double k) {
    const CohesivePair& p = pull.pair;
    const double gamma = anchorOf(open, pull.U[i], pull.V[i]);
    const Eigen::Matrix2d& R = turn[pull.chain * slots_ + i];
    const Eigen::Vector2d du = u - open * R * pull.U[i], dv = v - open * R * pull.V[i];
    const Eigen::Matrix2d B = angles.of(p.a) * pull.R[i];
    energy += k * (du.squaredNorm() + du.dot(dv) + dv.squaredNorm() + gamma * (R - B).squaredNorm());
    // gamma |R - Rot(theta) B|^2 = gamma (4 - 4 cos(phi_R - theta - beta)): d/d theta = 4 gamma (R^T B)(1, 0).
    if (angleGradient && !angleGradient->empty())
      (*angleGradient)[static_cast<size_t>(angles.groups->groupOf(p.a))] += k * gamma * 4 * (R.transpose() * B)(1, 0);
    // R minimizes the chain's energy, so the gradient is the one at fixed R.
    const Eigen::Vector2d gu = k * (2.0 * du + dv), gv = k * (du + 2.0 * dv);
    gradient.row(p.a) += gu.transpose();
    gradient.row(p.c) -= gu.transpose();
    gradient.row(p.b) += gv.transpose();
    gradient.row(p.d) -= gv.transpose();
  });
  return energy;
}

}  // namespace ib

