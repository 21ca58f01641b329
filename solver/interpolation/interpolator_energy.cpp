// The interpolation energy at one iterate (docs/solver.md, "Energies"): E = E_P + the springs'
// energy + E_D (eq. 9) + E_C (eq. 11) + E_O (non-overlap), with its gradient (n x 2), and the rigid
// placement of an iterate by the groups its links hold together.
#include "interpolation/interpolator_impl.h"

#include <cmath>
#include <omp.h>
#include <stdexcept>

namespace ib {

namespace {

// E_S = 1/2 sum_v c_v |x_v - y_v|^2, its gradient added to g. Summed serially: bit-identical
// results for any thread count.
double springEnergyOf(const Eigen::VectorXd& c, const Eigen::MatrixX2d& target, const Eigen::MatrixX2d& x,
                      Eigen::MatrixX2d& g) {
  double energy = 0;
  for (Eigen::Index v = 0; v < x.rows(); ++v) {
    const double dx = x(v, 0) - target(v, 0), dy = x(v, 1) - target(v, 1);
    energy += c(v) * (dx * dx + dy * dy);
    g(v, 0) += c(v) * dx;
    g(v, 1) += c(v) * dy;
  }
  return 0.5 * energy;
}

}  // namespace

void Interpolator::Impl::evaluateState(const Frame& frame, State& s) const {
  const int n = vertexCount();
  s.gradient.resize(n, 2);
  // E_P first: it also initializes the gradient. Each thread sums its own vertices; the sums
  // are added in block order (an OpenMP reduction would add them in arrival order, and frames
  // must be bit-identical from run to run).
  const double tie = options_.placementStiffness * vertexWeight_;  // mu m_v, or per vertex:
  const double* ties = placementTie_.size() ? placementTie_.data() : nullptr;
  const double *x = s.x.col(0).data(), *y = s.x.col(1).data();
  const double *bx = frame.blend.col(0).data(), *by = frame.blend.col(1).data();
  double *gx = s.gradient.col(0).data(), *gy = s.gradient.col(1).data();
  const int blocks = vertexSplit_.threads();
  std::vector<double> partial(static_cast<size_t>(blocks), 0.0);
#pragma omp parallel num_threads(teamFor(blocks))
  for (int p = omp_get_thread_num(); p < blocks; p += omp_get_num_threads()) {
    double sum = 0;
    if (ties) {
#pragma omp simd reduction(+ : sum)
      for (int v = vertexSplit_.begin(p); v < vertexSplit_.end(p); ++v) {
        const double dx = x[v] - bx[v], dy = y[v] - by[v];
        sum += ties[v] * (dx * dx + dy * dy);
        gx[v] = ties[v] * dx;
        gy[v] = ties[v] * dy;
      }
    } else {
#pragma omp simd reduction(+ : sum)
      for (int v = vertexSplit_.begin(p); v < vertexSplit_.end(p); ++v) {
        const double dx = x[v] - bx[v], dy = y[v] - by[v];
        sum += dx * dx + dy * dy;
        gx[v] = tie * dx;
        gy[v] = tie * dy;
      }
    }
    partial[p] = sum;
  }
  double placement = 0;
  for (double part : partial) placement += part;
  s.placement = 0.5 * (ties ? placement : tie * placement);
  s.energy = s.placement;
  if (frame.springs.size()) s.energy += springEnergyOf(frame.springs, frame.springTarget, s.x, s.gradient);
  s.energy += deformation_->evaluate(s.x, frame.keys, s.gradient, vertexSplit_, triangleSplit_, params_.metric);
  s.energy += cohesive_->evaluate(s.x, frame.w, s.gradient, s.held);
  addGapPull(frame, s);
  s.contacts.clear();
  if (params_.nonOverlap) s.energy += nonOverlap_->evaluate(s.x, frame.participants, s.gradient, s.contacts);
}

void Interpolator::Impl::addGapPull(const Frame& frame, State& s) const {
  bool pulling = false;
  for (int p = 0; p < gapPull_->size() && !pulling; ++p) pulling = gapPull_->springConstant(p, frame.w) > 0;
  if (!pulling) return;
  // Each group's angle from the frame's blend (Procrustes, as align: atan2(sum m a x b, sum m a . b)
  // with a, b the group's positions in x and in the blend, centred on their m-weighted centroids,
  // m the placement weights, turns x onto the blend, so x stands turned by minus that). W_G's
  // anchors turn with it: W_G is invariant under a turn of the group, and align's turn (by E_P
  // alone) is a true minimization. Its gradient carries d W_G / d angle through
  // d angle / d x_v = -m_v (D (b_y, -b_x) - C b) / (C^2 + D^2), C and D the two sums.
  const int groups = groups_.groupCount();
  const auto& start = groups_.memberStart();
  const auto& members = groups_.members();
  GroupAngles angles{&groups_, std::vector<double>(static_cast<size_t>(groups), 0.0)};
  std::vector<Eigen::Vector2d> centre(static_cast<size_t>(groups)), target(static_cast<size_t>(groups));
  std::vector<double> dots(static_cast<size_t>(groups)), crosses(static_cast<size_t>(groups));
  const auto weight = [this](int v) { return placementWeight_.size() ? placementWeight_(v) : 1.0; };
  for (int k = 0; k < groups; ++k) {
    Eigen::Vector2d c(0, 0), q(0, 0);
    double mass = 0;
    for (int i = start[k]; i < start[k + 1]; ++i) {
      const double m = weight(members[i]);
      mass += m;
      c += m * s.x.row(members[i]).transpose();
      q += m * frame.blend.row(members[i]).transpose();
    }
    if (mass <= 0) mass = 1;
    centre[k] = c / mass;
    target[k] = q / mass;
    double dot = 0, cross = 0;
    for (int i = start[k]; i < start[k + 1]; ++i) {
      const int v = members[i];
      const double m = weight(v);
      const Eigen::Vector2d a = s.x.row(v).transpose() - centre[k], b = frame.blend.row(v).transpose() - target[k];
      dot += m * a.dot(b);
      cross += m * (a.x() * b.y() - a.y() * b.x());
    }
    dots[k] = dot;
    crosses[k] = cross;
    angles.angle[k] = -std::atan2(cross, dot);
  }
  std::vector<double> dAngle(static_cast<size_t>(groups), 0.0);
  s.energy += gapPull_->evaluate(s.x, frame.w, s.gradient, angles, &dAngle);
  for (int k = 0; k < groups; ++k) {
    const double n = dots[k] * dots[k] + crosses[k] * crosses[k];
    if (dAngle[k] == 0 || n <= 0) continue;
    for (int i = start[k]; i < start[k + 1]; ++i) {
      const int v = members[i];
      const Eigen::Vector2d b = weight(v) * (frame.blend.row(v).transpose() - target[k]);
      const Eigen::Vector2d dTheta = -(dots[k] * Eigen::Vector2d(b.y(), -b.x()) - crosses[k] * b) / n;
      s.gradient.row(v) += dAngle[k] * dTheta.transpose();
    }
  }
}

void Interpolator::Impl::evaluateLinks(const Frame& frame, State& s) const {
  Eigen::MatrixX2d scratch = Eigen::MatrixX2d::Zero(vertexCount(), 2);
  cohesive_->evaluate(s.x, frame.w, scratch, s.held);
  s.contacts.clear();
  if (params_.nonOverlap) nonOverlap_->evaluate(s.x, frame.participants, scratch, s.contacts);
}

void Interpolator::Impl::align(const Frame& frame, const State& reference, Eigen::MatrixX2d& x) {
  std::vector<std::pair<int, int>> links = reference.contacts;
  const auto& terms = cohesive_->terms();
  for (size_t j = 0; j < terms.size(); ++j)
    if (j < reference.held.size() && reference.held[j]) {
      links.push_back({terms[j].pair.a, terms[j].pair.c});
      links.push_back({terms[j].pair.b, terms[j].pair.d});
    }
  // The gap pull places the pieces it joins relative to each other, as a held pair does.
  for (int p = 0; p < gapPull_->size(); ++p)
    if (gapPull_->springConstant(p, frame.w) > 0) {
      links.push_back({gapPull_->pair(p).a, gapPull_->pair(p).c});
      links.push_back({gapPull_->pair(p).b, gapPull_->pair(p).d});
    }
  if (links != groupLinks_) {
    groups_.update(links);
    groupLinks_ = std::move(links);
  }
  alignGroups(x, frame.blend, groups_, vertexSplit_, placementWeight_);
}

EnergyEvaluation Interpolator::Impl::evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const {
  if (x.rows() != vertexCount()) throw std::invalid_argument("positions: expected " + std::to_string(vertexCount()) + " rows");
  const Frame frame = makeFrame(w, nullptr);
  State s;
  s.x = toLayout(x, originalOf_) / scale_;
  evaluateState(frame, s);
  return {s.energy, fromLayout(s.gradient, originalOf_) / scale_};
}

int Interpolator::Impl::countOverlaps(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const {
  if (x.rows() != vertexCount()) throw std::invalid_argument("positions: expected " + std::to_string(vertexCount()) + " rows");
  return nonOverlap_->countInside(toLayout(x, originalOf_) / scale_, makeFrame(w, nullptr).participants);
}

}  // namespace ib
