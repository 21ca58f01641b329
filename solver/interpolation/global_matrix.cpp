#include "interpolation/global_matrix.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace ib {

GlobalMatrix::GlobalMatrix(GlobalMatrixSources sources, int vertices, std::vector<int> partStart, int threads)
    : sources_(sources), vertices_(vertices), assembly_(vertices), factor_(threads) {
  factor_.setPreordered(std::move(partStart));
}

const Eigen::SparseMatrix<double>& GlobalMatrix::assemble(const GlobalMatrixFrame& frame) {
  const DeformationEnergy& deformation = *sources_.deformation;
  const CohesiveEnergy& cohesive = *sources_.cohesive;
  const auto& triangles = deformation.triangles();
  const ActiveKeys keys = activeKeys(frame.w);
  assembly_.begin();
  Eigen::Matrix<double, 2, 3> E;  // edge vectors of a triangle from its corners
  E << -1, 1, 0, -1, 0, 1;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Matrix3d K = E.transpose() * deformation.metric(static_cast<int>(t), keys) * E;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) assembly_.add(triangles[t][r], triangles[t][c], K(r, c));
  }
  const auto& terms = cohesive.terms();
  for (size_t j = 0; j < terms.size(); ++j) {
    const CohesivePair& p = terms[j].pair;
    // k S [[2,1],[1,2]] S^T with S = [e_a - e_c, e_b - e_d]; zeros keep the pattern when clamped.
    const bool on = j < frame.held.size() && frame.held[j];
    const double k = on ? cohesive.termWeight(static_cast<int>(j), frame.w) * cohesive.springConstant(static_cast<int>(j)) : 0.0;
    const int vert[4] = {p.a, p.c, p.b, p.d};
    const double sign[4] = {1, -1, 1, -1};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        const double block = (r / 2 == c / 2) ? 2.0 : 1.0;
        assembly_.add(vert[r], vert[c], k * block * sign[r] * sign[c]);
      }
  }
  // The gap pull's springs, the same form on the same entries (gap_pull.h), whatever is held.
  for (int j = 0; sources_.gapPull && j < sources_.gapPull->size(); ++j) {
    const CohesivePair& p = sources_.gapPull->pair(j);
    const double k = sources_.gapPull->springConstant(j, frame.w);
    const int vert[4] = {p.a, p.c, p.b, p.d};
    const double sign[4] = {1, -1, 1, -1};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) assembly_.add(vert[r], vert[c], k * ((r / 2 == c / 2) ? 2.0 : 1.0) * sign[r] * sign[c]);
  }
  for (int v = 0; v < vertices_; ++v)
    assembly_.add(v, v, (sources_.ties ? (*sources_.ties)(v) : sources_.tie) + (frame.springs.size() ? frame.springs(v) : 0.0));
  if (sources_.nonOverlap) {
    const double k = sources_.enforceNonOverlap ? sources_.nonOverlap->stiffness() : 0.0;
    for (int v : sources_.nonOverlap->allBoundaryVertices()) assembly_.add(v, v, k);
  }
  return assembly_.matrix();
}

long GlobalMatrix::updateCost(const std::vector<char>& held) const {
  if (!valid_ || held.size() != held_.size()) throw std::logic_error("global matrix: no factor to update");
  const auto& terms = sources_.cohesive->terms();
  long cost = 0;
  for (size_t j = 0; j < held.size(); ++j)
    if (held[j] != held_[j] && sources_.cohesive->termWeight(static_cast<int>(j), weights_) != 0) {
      const CohesivePair& p = terms[j].pair;
      cost += 2 * factor_.updateCost(std::min(std::min(p.a, p.b), std::min(p.c, p.d)));
    }
  return cost;
}

bool GlobalMatrix::updateHeld(const std::vector<char>& held) {
  if (!valid_ || held.size() != held_.size()) throw std::logic_error("global matrix: no factor to update");
  const CohesiveEnergy& cohesive = *sources_.cohesive;
  const auto& terms = cohesive.terms();
  // k S [[2,1],[1,2]] S^T = 3k/2 v1 v1^T + k/2 v2 v2^T with v1 = S (1, 1), v2 = S (1, -1). Springs
  // that engage go first, so every intermediate H is positive definite.
  for (int pass = 0; pass < 2; ++pass)
    for (size_t j = 0; j < held.size(); ++j) {
      const bool engages = held[j] && !held_[j];
      const double weight = cohesive.termWeight(static_cast<int>(j), weights_);
      if (held[j] == held_[j] || engages != (pass == 0) || weight == 0) continue;
      const CohesivePair& p = terms[j].pair;
      const double k = weight * cohesive.springConstant(static_cast<int>(j));
      const double sigma = engages ? 1.0 : -1.0;
      const double a1 = std::sqrt(1.5 * k), a2 = std::sqrt(0.5 * k);
      try {
        factor_.rankOneUpdate({p.a, p.c, p.b, p.d}, {a1, -a1, a1, -a1}, sigma);
        factor_.rankOneUpdate({p.a, p.c, p.b, p.d}, {a2, -a2, -a2, a2}, sigma);
      } catch (const std::runtime_error&) {
        // A downdate lost definiteness to rounding; the factor is spoilt, so build it afresh.
        factorize({weights_, springs_, held});
        return false;
      }
    }
  held_ = held;
  return true;
}

void GlobalMatrix::setSources(const GlobalMatrixSources& sources) {
  if (sources.deformation != sources_.deformation || sources.cohesive != sources_.cohesive || sources.gapPull != sources_.gapPull ||
      sources.nonOverlap != sources_.nonOverlap)
    throw std::logic_error("global matrix: new sources must keep the energies (and so H's pattern)");
  sources_ = sources;
  valid_ = false;
}

void GlobalMatrix::factorize(const GlobalMatrixFrame& frame) {
  valid_ = false;  // stays false if the factorization throws
  factor_.factorize(assemble(frame));
  weights_ = frame.w;
  springs_ = frame.springs;
  held_ = frame.held;
  valid_ = true;
}

// None on both sides, or every c_v within a fifth of H's (plus a small absolute slack, so springs
// fading to zero do not refactorize every frame).
bool GlobalMatrix::springsMatch(const Eigen::VectorXd& springs) const {
  if (springs.size() == 0 || springs_.size() == 0) return springs.size() == springs_.size();
  const double slack = 0.02 * sources_.stiffnessScale;
  for (Eigen::Index v = 0; v < springs.size(); ++v)
    if (std::abs(springs(v) - springs_(v)) > 0.1 * (springs(v) + springs_(v)) + slack) return false;
  return true;
}

bool GlobalMatrix::models(const GlobalMatrixFrame& frame, double refactorDistance) const {
  return valid_ && (frame.w - weights_).lpNorm<1>() <= refactorDistance &&
         (refactorDistance > 0 || frame.w == weights_) && frame.held == held_ && springsMatch(frame.springs) &&
         rampsMatch(frame.w);
}

bool GlobalMatrix::rampsMatch(const Eigen::VectorXd& w) const {
  // Within a release window a cut's springs change with w much faster than the rest of H (the
  // closing pull fades and the gap pull grows over a few frames): H follows them within a tenth.
  const CohesiveEnergy& cohesive = *sources_.cohesive;
  for (int j = 0; j < static_cast<int>(cohesive.terms().size()); ++j)
    if (std::abs(cohesive.ramp(j, w) - cohesive.ramp(j, weights_)) > 0.1) return false;
  for (int p = 0; sources_.gapPull && p < sources_.gapPull->size(); ++p)
    if (std::abs(sources_.gapPull->strength(p, w) - sources_.gapPull->strength(p, weights_)) > 0.1) return false;
  return true;
}

}  // namespace ib
