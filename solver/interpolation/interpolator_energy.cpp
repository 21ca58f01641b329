// The interpolation energy at one iterate (docs/solver.md, "Energies"): E = E_P + the springs'
// energy + E_D (eq. 9) + E_C (eq. 11) + E_O (non-overlap), with its gradient (n x 2), and the rigid
// placement of an iterate by the groups its links hold together.
#include "interpolation/interpolator_impl.h"

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

void Interpolator::Impl::evaluateState(const Frame& frame, State& s, bool placed) const {
  const int n = vertexCount();
  s.gradient.resize(n, 2);
  // E_P first: it also initializes the gradient. Each thread sums its own vertices; the sums
  // are added in block order (an OpenMP reduction would add them in arrival order, and frames
  // must be bit-identical from run to run).
  const double tie = options_.placementStiffness * vertexWeight_;  // mu m_v
  const double *x = s.x.col(0).data(), *y = s.x.col(1).data();
  const double *bx = frame.blend.col(0).data(), *by = frame.blend.col(1).data();
  double *gx = s.gradient.col(0).data(), *gy = s.gradient.col(1).data();
  const int blocks = vertexSplit_.threads();
  std::vector<double> partial(static_cast<size_t>(blocks), 0.0);
#pragma omp parallel num_threads(teamFor(blocks))
  for (int p = omp_get_thread_num(); p < blocks; p += omp_get_num_threads()) {
    double sum = 0;
#pragma omp simd reduction(+ : sum)
    for (int v = vertexSplit_.begin(p); v < vertexSplit_.end(p); ++v) {
      const double dx = x[v] - bx[v], dy = y[v] - by[v];
      sum += dx * dx + dy * dy;
      gx[v] = tie * dx;
      gy[v] = tie * dy;
    }
    partial[p] = sum;
  }
  double placement = 0;
  for (double part : partial) placement += part;
  s.placement = 0.5 * tie * placement;
  s.energy = s.placement;
  if (frame.springs.size()) s.energy += springEnergyOf(frame.springs, frame.springTarget, s.x, s.gradient);
  s.energy += deformation_->evaluate(s.x, frame.keys, s.gradient, vertexSplit_, triangleSplit_, params_.metric);
  s.energy += cohesive_->evaluate(s.x, frame.w, s.gradient, s.held);
  s.energy += gapPull_->evaluate(s.x, frame.w, s.gradient);
  if (placed) projectTurns(frame, s);
  s.contacts.clear();
  if (params_.nonOverlap) s.energy += nonOverlap_->evaluate(s.x, frame.participants, s.gradient, s.contacts);
}

void Interpolator::Impl::projectTurns(const Frame& frame, State& s) const {
  // W_G's anchor to the frozen rotations B_j is not invariant under a turn of the group it joins,
  // but the placement turns every group by E_P alone (align): the gradient's turn component there
  // is not the iteration's to reduce, and the stopping rule would wait for it in vain
  // (continental-drift: 500 iterations at E constant to 8 digits). It is taken out, per group
  // with an active pull.
  std::vector<char> pulled(static_cast<size_t>(groups_.groupCount()), 0);
  bool any = false;
  for (int p = 0; p < gapPull_->size(); ++p)
    if (gapPull_->springConstant(p, frame.w) > 0) {
      pulled[groups_.groupOf(gapPull_->pair(p).a)] = 1;
      any = true;
    }
  if (!any) return;
  const auto& start = groups_.memberStart();
  const auto& members = groups_.members();
  for (int k = 0; k < groups_.groupCount(); ++k) {
    if (!pulled[k]) continue;
    Eigen::Vector2d c(0, 0);
    for (int i = start[k]; i < start[k + 1]; ++i) c += s.x.row(members[i]).transpose();
    c /= std::max(1, start[k + 1] - start[k]);
    double torque = 0, inertia = 0;
    for (int i = start[k]; i < start[k + 1]; ++i) {
      const int v = members[i];
      const double px = s.x(v, 0) - c.x(), py = s.x(v, 1) - c.y();
      torque += px * s.gradient(v, 1) - py * s.gradient(v, 0);
      inertia += px * px + py * py;
    }
    if (inertia <= 0) continue;
    const double turn = torque / inertia;
    for (int i = start[k]; i < start[k + 1]; ++i) {
      const int v = members[i];
      const double px = s.x(v, 0) - c.x(), py = s.x(v, 1) - c.y();
      s.gradient(v, 0) += turn * py;
      s.gradient(v, 1) -= turn * px;
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
  alignGroups(x, frame.blend, groups_, vertexSplit_);
}

EnergyEvaluation Interpolator::Impl::evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const {
  if (x.rows() != vertexCount()) throw std::invalid_argument("positions: expected " + std::to_string(vertexCount()) + " rows");
  const Frame frame = makeFrame(w, nullptr);
  State s;
  s.x = toLayout(x, originalOf_) / scale_;
  evaluateState(frame, s, false);  // the true gradient: x was not placed by align
  return {s.energy, fromLayout(s.gradient, originalOf_) / scale_};
}

int Interpolator::Impl::countOverlaps(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const {
  if (x.rows() != vertexCount()) throw std::invalid_argument("positions: expected " + std::to_string(vertexCount()) + " rows");
  return nonOverlap_->countInside(toLayout(x, originalOf_) / scale_, makeFrame(w, nullptr).participants);
}

}  // namespace ib
