#include "interpolation/cohesive_energy.h"

#include <algorithm>
#include <cmath>

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
    const double weight = w(t.key);
    if (weight <= 0) continue;
    const CohesivePair& p = t.pair;
    const Eigen::Vector2d u = (x.row(p.a) - x.row(p.c)).transpose();
    const Eigen::Vector2d v = (x.row(p.b) - x.row(p.d)).transpose();
    const Eigen::Vector2d s = (x.row(p.a) + x.row(p.c) - x.row(p.b) - x.row(p.d)).transpose();
    const double sn = s.norm();
    const Eigen::Vector2d xhat = sn > 1e-12 * t.restLength ? Eigen::Vector2d(s / sn) : t.restDirection;
    const Eigen::Matrix2d P =
        params_.alpha * Eigen::Matrix2d::Identity() + (1.0 - 2.0 * params_.alpha) * xhat * xhat.transpose();
    const Eigen::Vector2d Pu = P * u, Pv = P * v;
    const double scale = t.restLength / 3.0 * params_.lambda;
    const double q = scale * (u.dot(Pu) + u.dot(Pv) + v.dot(Pv));
    if (q < params_.tau) {
      held[j] = 1;
      energy += weight * q;
      const Eigen::Vector2d gu = weight * scale * (2.0 * Pu + Pv);
      const Eigen::Vector2d gv = weight * scale * (Pu + 2.0 * Pv);
      gradient.row(p.a) += gu.transpose();
      gradient.row(p.c) -= gu.transpose();
      gradient.row(p.b) += gv.transpose();
      gradient.row(p.d) -= gv.transpose();
      if (sn > 1e-12 * t.restLength && params_.alpha != 0.5) {
        // Through xhat = s / |s|: dq/dxhat = (1 - 2 alpha) scale [2(xhat.u) u + (xhat.v) u +
        // (xhat.u) v + 2(xhat.v) v], and dxhat/ds = (Id - xhat xhat^T) / |s|.
        const double xu = xhat.dot(u), xv = xhat.dot(v);
        const Eigen::Vector2d h = (1.0 - 2.0 * params_.alpha) * scale * ((2 * xu + xv) * u + (xu + 2 * xv) * v);
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
