#include "interpolation/cohesive_energy.h"

#include "multimesh/cut_chains.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ib {

CohesiveEnergy::CohesiveEnergy(const Multimesh& mesh, const std::vector<Eigen::MatrixX2d>& keys,
                               const CohesiveParams& params)
    : params_(params) {
  for (int i = 0; i < mesh.keyCount(); ++i)
    for (const CohesivePair& p : mesh.cohesivePairs(i)) {
      CohesiveTerm term;
      term.key = i;
      term.pair = p;
      const Eigen::Vector2d edge = (keys[i].row(p.a) - keys[i].row(p.b)).transpose();
      term.restLength = edge.norm();
      term.restDirection = edge / term.restLength;
      terms_.push_back(term);
    }
  const CutChains cuts = cutChains(mesh);
  for (CohesiveTerm& t : terms_) {
    const int id = cuts.indexOf(t.pair);
    t.closedIn = cuts.closedIn[id];
    t.cut = cuts.chainOf[id];
  }
  letGo_.resize(static_cast<size_t>(cuts.chains));
}

namespace {

// The open keys' total weight for a term: sum of w_k over the keys that do not close its pair.
double openWeight(const CohesiveTerm& t, const Eigen::VectorXd& w) {
  double open = 0;
  for (Eigen::Index k = 0; k < w.size(); ++k)
    if (!t.closedIn[k]) open += w(k);
  return open;
}

}  // namespace

double releaseRamp(double openWeight, double release, double window) {
  const double lo = std::max(0.0, release - 0.5 * window);
  const double hi = std::min(1.0, release + 0.5 * window);
  if (openWeight <= lo) return 1;
  if (openWeight >= hi) return 0;
  const double u = (openWeight - lo) / (hi - lo);
  // The gap (1 - r) o follows hi G(u), G = 2u^2 - u^3: it leaves the glued sides at rest (G'(0) =
  // 0) and grows at most 4/3 as fast as the weights (at u = 2/3), where (1 - r) = smoothstep(u)
  // made it 1.69 (at o = 0.75).
  const double gap = hi * u * u * (2 - u);
  return std::clamp(1 - gap / openWeight, 0.0, 1.0);
}

double releaseRamp(double openWeight, const CohesiveParams& params) {
  return releaseRamp(openWeight, params.release, params.releaseWindow);
}

double pullFade(double openWeight, double release, double window) {
  const double hi = std::min(1.0, release + 0.5 * window);
  if (openWeight <= hi) return 1;
  const double end = std::min(1.0, hi + window);
  if (openWeight >= end) return 0;
  const double u = (openWeight - hi) / (end - hi);
  return 1 - u * u * (3 - 2 * u);
}

CutRelease timingOf(int term, const CohesiveParams& params) {
  CutRelease own = term >= 0 && term < static_cast<int>(params.perTerm.size()) ? params.perTerm[term] : CutRelease{};
  if (std::isnan(own.release)) own.release = params.release;
  if (std::isnan(own.window)) own.window = params.releaseWindow;
  return own;
}

double CohesiveEnergy::termWeight(int term, const Eigen::VectorXd& w) const {
  const CohesiveTerm& t = terms_[term];
  const double weight = w(t.key);
  if (params_.timing == CutTiming::kTau || weight <= 0) return weight;
  // The closing keys share r between them (their weights sum to 1 - o), the open keys 1 - r
  // (gap_pull.h): the gap is then (1 - r) of the drawn one, whatever the weights' split.
  const double open = openWeight(t, w);
  return open < 1 ? ramp(term, w) * weight / (1 - open) : 0.0;
}

double CohesiveEnergy::ramp(int term, const Eigen::VectorXd& w) const {
  if (params_.timing == CutTiming::kTau) return 1.0;
  const CutRelease own = timingOf(term, params_);
  return releaseRamp(openWeight(terms_[term], w), own.release, own.window);
}

bool CohesiveEnergy::glued(int term, const Eigen::VectorXd& w) const {
  const CohesiveTerm& t = terms_[term];
  return w(t.key) > 0 && ramp(term, w) == 1;
}

void CohesiveEnergy::letGo(const std::vector<char>& held, const Eigen::VectorXd& w) {
  if (params_.timing != CutTiming::kTau) return;
  if (lastWeights_.size() == w.size() && lastWeights_ != w)
    for (size_t j = 0; j < terms_.size() && j < held.size(); ++j) {
      LetGo& cut = letGo_[terms_[j].cut];
      if (!held[j] && cut.at.size() == 0 && termWeight(static_cast<int>(j), w) > 0) cut = {w, w - lastWeights_};
    }
  lastWeights_ = w;
}

void CohesiveEnergy::holdAgain(const Eigen::VectorXd& w) {
  for (LetGo& g : letGo_)
    if (g.at.size() == w.size() && (w - g.at).dot(g.direction) < 0) g = LetGo{};
}

void CohesiveEnergy::forgetLetGo() {
  for (LetGo& g : letGo_) g = LetGo{};
  lastWeights_.resize(0);
}

double CohesiveEnergy::springConstant(int term) const {
  return terms_[term].restLength / 3.0 * params_.lambda * std::max(params_.alpha, 1.0 - params_.alpha);
}

double CohesiveEnergy::evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, Eigen::MatrixX2d& gradient,
                                std::vector<char>& held) const {
  held.assign(terms_.size(), 0);
  double energy = 0;
  for (size_t j = 0; j < terms_.size(); ++j) {
    const CohesiveTerm& t = terms_[j];
    const double weight = termWeight(static_cast<int>(j), w);
    if (weight <= 0) continue;
    if (params_.timing == CutTiming::kTau && letGo_[t.cut].at.size() > 0) {
      energy += weight * params_.tau;  // let go in an earlier frame (letGo): clamped
      continue;
    }
    const CohesivePair& p = t.pair;
    const Eigen::Vector2d u = (x.row(p.a) - x.row(p.c)).transpose();
    const Eigen::Vector2d v = (x.row(p.b) - x.row(p.d)).transpose();
    const Eigen::Vector2d s = (x.row(p.a) + x.row(p.c) - x.row(p.b) - x.row(p.d)).transpose();
    const double sn = s.norm();
    const Eigen::Vector2d xhat = sn > 1e-12 * t.restLength ? Eigen::Vector2d(s / sn) : t.restDirection;
    // Under CutTiming::kRelease alpha holds while the seam is glued (r = 1); a seam that lets go is
    // isotropic (alpha = 1/2). At alpha != 1/2 the term depends on the seam's direction xhat, with
    // curvature growing as (gap / edge)^2, and no tau clamps a parting seam: cell-splitting's
    // solves stalled or ran to the cap on 16 frames with alpha eased as r^2, none with this. The
    // switch costs nothing visible: where r leaves 1 the gap is still closed.
    const double r = params_.timing == CutTiming::kRelease ? ramp(static_cast<int>(j), w) : 1.0;
    const double alpha = r >= 1 ? params_.alpha : 0.5;
    const Eigen::Matrix2d P = alpha * Eigen::Matrix2d::Identity() + (1.0 - 2.0 * alpha) * xhat * xhat.transpose();
    const Eigen::Vector2d Pu = P * u, Pv = P * v;
    const double scale = t.restLength / 3.0 * params_.lambda;
    const double q = scale * (u.dot(Pu) + u.dot(Pv) + v.dot(Pv));
    if (q < params_.tau || params_.timing == CutTiming::kRelease) {
      held[j] = 1;
      energy += weight * q;
      const Eigen::Vector2d gu = weight * scale * (2.0 * Pu + Pv);
      const Eigen::Vector2d gv = weight * scale * (Pu + 2.0 * Pv);
      gradient.row(p.a) += gu.transpose();
      gradient.row(p.c) -= gu.transpose();
      gradient.row(p.b) += gv.transpose();
      gradient.row(p.d) -= gv.transpose();
      if (sn > 1e-12 * t.restLength && alpha != 0.5) {
        // Through xhat = s / |s|: dq/dxhat = (1 - 2 alpha) scale [2(xhat.u) u + (xhat.v) u +
        // (xhat.u) v + 2(xhat.v) v], and dxhat/ds = (Id - xhat xhat^T) / |s|.
        const double xu = xhat.dot(u), xv = xhat.dot(v);
        const Eigen::Vector2d h = (1.0 - 2.0 * alpha) * scale * ((2 * xu + xv) * u + (xu + 2 * xv) * v);
        const Eigen::Vector2d gs = weight * (h - xhat * xhat.dot(h)) / sn;
        gradient.row(p.a) += gs.transpose();
        gradient.row(p.c) += gs.transpose();
        gradient.row(p.b) -= gs.transpose();
        gradient.row(p.d) -= gs.transpose();
      }
    } else {
      energy += weight * params_.tau;
    }
  }
  return energy;
}

}  // namespace ib
