#include "comesh/comesh.h"

#include "comesh/comesh_block_energy.h"
#include "comesh/comesh_energy.h"
#include "comesh/comesh_preconditioner.h"
#include "core/thread_budget.h"
#include "multimesh/mesh_quality.h"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <omp.h>

namespace ib {

namespace {

// One projected gradient step on key i (paper: gradient_descent_step), with per-vertex bisection.
class VertexStepper {
 public:
  // Halvings of the step a vertex tries before it stays where it is.
  static constexpr int kHalvings = 30;
  struct Bounds {
    double minimumGap, maximumGap, chordTolerance;  // px
  };
  // `energy` is prepared for key `key` on the first step; it is passed in so that its arrays are
  // reused from key to key.
  VertexStepper(ComeshMesh& mesh, SobolevPreconditioner& preconditioner, BlockEnergy& energy, int key,
                double odtWeight, const Bounds& bounds)
      : mesh_(mesh), preconditioner_(preconditioner), energy_(energy), key_(key), odtWeight_(odtWeight),
        minimumGap_(bounds.minimumGap), maximumGap_(bounds.maximumGap), chordTolerance_(bounds.chordTolerance) {}

  // Returns the energy decrease relative to `objective` (eq. 8 when the sweep started; the block
  // energy itself if that is not a positive number), 0 when no step lowered the energy.
  // `stepSize` carries over between calls: it grows after a success and shrinks while a step fails.
  double step(double& stepSize, double objective) {
    if (preparedVersion_ < 0) energy_.prepare(mesh_.triangles, mesh_.keys, key_, odtWeight_);
    else if (mesh_.topologyVersion != preparedVersion_) energy_.update(mesh_.triangles, mesh_.keys);
    preparedVersion_ = mesh_.topologyVersion;  // the other keys hold still while this stepper lives
    Eigen::MatrixX2d gradient;
    const double before = energy_.evaluate(mesh_.keys[key_], &gradient);
    const int n = mesh_.vertexCount();
    preconditioner_.update(mesh_);
    preconditioner_.apply(mesh_, gradient, direction_);
    slide_.setZero(n);
    for (int v = 0; v < n; ++v) {
      if (mesh_.fixed[v] || mesh_.around[v].empty()) {
        direction_.row(v).setZero();
      } else if (mesh_.onBoundary(v)) {  // along the outline only, or not at all
        const Eigen::Vector2d t = mesh_.slides(v, key_) ? tangent(v) : Eigen::Vector2d::Zero();
        slide_[v] = t.isZero() ? 0.0 : direction_.row(v).dot(t.transpose()) / t.squaredNorm();
        direction_.row(v) = slide_[v] * t.transpose();
      }
    }
    const double largest = direction_.rowwise().norm().maxCoeff();
    if (!(largest > 0)) return 0;
    const Eigen::MatrixX2d start = mesh_.keys[key_];
    const Eigen::VectorXd startU = mesh_.u.col(key_);
    if (!(stepSize > 0)) stepSize = 0.1 * meanEdge(start) / largest;
    // A step that lowers eq. 8 may still thin a sliver: ODT evens triangle sizes out, so next to
    // a boundary edge much shorter than the mesh around it (a tip's outline needs them) it pulls
    // the inside vertex away, and the ear between them thinned to 1-2 degrees. The vertices of
    // every triangle a step would leave under kSliverDegrees and thinner than before are held
    // still and the step is searched again without them, up to kSliverRounds times.
    constexpr int kSliverRounds = 4;
    for (int round = 0; round <= kSliverRounds; ++round) {
      double trial = stepSize;
      bool again = false;
      for (int attempt = 0; attempt < 20 && !again; ++attempt) {
        // The block energy is infinite when a triangle is not positive in key i (or in a
        // neighbour, which no step can change): it is the positivity check of the interior's joint move.
        moveTogether(start, startU, trial);
        double after = energy_.evaluate(mesh_.keys[key_], nullptr);
        if (!(after < std::numeric_limits<double>::infinity())) {
          moveOneByOne(start, startU, trial);
          after = energy_.evaluate(mesh_.keys[key_], nullptr);
        }
        if (after < before) {
          again = round < kSliverRounds && holdSlivers(start);  // then search again, those held
          if (again) continue;
          stepSize = trial * 1.5;
          return (before - after) / (objective > 0 && std::isfinite(objective) ? objective : before);
        }
        trial *= 0.5;
      }
      if (!again) {
        stepSize = trial;
        break;
      }
    }
    mesh_.keys[key_] = start;
    mesh_.u.col(key_) = startU;
    return 0;
  }

 private:
  // The sine of triangle c's smallest angle at positions x (0 when it is not positive): the
  // smallest angle faces the shortest edge, sin = 2 area / (the other two edges' product).
  static double smallestSine(const Eigen::MatrixX2d& x, const Triangle& c) {
    const Eigen::Vector2d a = x.row(c[0]), b = x.row(c[1]), d = x.row(c[2]);
    const double twice = (b - a).x() * (d - a).y() - (b - a).y() * (d - a).x();
    if (!(twice > 0)) return 0;
    const double ab = (b - a).norm(), bd = (d - b).norm(), da = (a - d).norm();
    const double shortest = std::min({ab, bd, da});
    return shortest == ab ? twice / (bd * da) : shortest == bd ? twice / (ab * da) : twice / (ab * bd);
  }

  // Stops (direction 0) the vertices of every triangle that the positions now in the key leave
  // under kSliverDegrees and thinner than at `start`; whether there were any.
  bool holdSlivers(const Eigen::MatrixX2d& start) {
    constexpr double kSliverDegrees = 10;
    const double floor = std::sin(kSliverDegrees * 3.14159265358979323846 / 180);
    const Eigen::MatrixX2d& x = mesh_.keys[key_];
    bool held = false;
    for (const Triangle& c : mesh_.triangles) {
      if (c[0] < 0) continue;
      const double now = smallestSine(x, c);
      if (!(now < floor && now < smallestSine(start, c))) continue;
      for (int v : c)
        if (x.row(v) != start.row(v)) {
          direction_.row(v).setZero();
          slide_[v] = 0;
          held = true;
        }
    }
    return held;
  }

  // d point / du at the vertex's place on its arc in this key (px per unit u).
  Eigen::Vector2d tangent(int v) const {
    const double u = mesh_.u(v, key_), h = 1e-4;
    const double lo = std::max(0.0, u - h), hi = std::min(1.0, u + h);
    return (mesh_.point(key_, mesh_.arc[v], hi) - mesh_.point(key_, mesh_.arc[v], lo)) / (hi - lo);
  }

  double meanEdge(const Eigen::MatrixX2d& x) const {
    double sum = 0;
    for (const Triangle& t : mesh_.triangles) sum += (x.row(t[1]) - x.row(t[0])).norm();
    return sum / std::max<size_t>(mesh_.triangles.size(), 1);
  }

  // Fraction range a sliding vertex must stay strictly inside: its walk neighbours' fractions.
  std::pair<double, double> slideRange(int v) const {
    const int p = mesh_.previous[v], q = mesh_.next[v];
    const double lo = (mesh_.arc[p] == mesh_.arc[v]) ? mesh_.u(p, key_) : 0.0;
    const double hi = (mesh_.arc[q] == mesh_.arc[v] && mesh_.u(q, key_) > 0) ? mesh_.u(q, key_) : 1.0;
    return {lo, hi};
  }

  // Every movable vertex goes `stepSize` along its direction from its start: the interior
  // vertices all at once, the sliding ones one by one, each halving its slide until it fits (its
  // one-ring positive, its gaps kept, the outline followed). Usually every triangle stays
  // positive; the caller checks, and if not, moves the vertices with moveOneByOne instead.
  void moveTogether(const Eigen::MatrixX2d& start, const Eigen::VectorXd& startU, double stepSize) {
    Eigen::MatrixX2d& x = mesh_.keys[key_];
    x = start;
    mesh_.u.col(key_) = startU;
    const int n = static_cast<int>(x.rows());
    for (int v = 0; v < n; ++v)
      if (slide_[v] == 0) x.row(v) += stepSize * direction_.row(v);  // zero rows for the still ones
    for (int v = 0; v < n; ++v)
      if (slide_[v] != 0) moveVertex(v, start, startU, stepSize);
  }

  // The same with every movable vertex going one by one, each halving its step until its one-ring
  // stays positive (and, sliding, until it fits as above).
  void moveOneByOne(const Eigen::MatrixX2d& start, const Eigen::VectorXd& startU, double stepSize) {
    Eigen::MatrixX2d& x = mesh_.keys[key_];
    x = start;
    mesh_.u.col(key_) = startU;
    for (int v = 0; v < static_cast<int>(x.rows()); ++v)
      if (!direction_.row(v).isZero() || slide_[v] != 0) moveVertex(v, start, startU, stepSize);
  }

  // Vertex v from its start, `stepSize` along its direction, halved until it fits, else back at its start.
  void moveVertex(int v, const Eigen::MatrixX2d& start, const Eigen::VectorXd& startU, double stepSize) {
    if (slide_[v] != 0) return slideVertex(v, start, startU, stepSize);
    Eigen::MatrixX2d& x = mesh_.keys[key_];
    double scale = stepSize;
    for (int halving = 0; halving < kHalvings; ++halving, scale *= 0.5) {
      x.row(v) = start.row(v) + scale * direction_.row(v);
      if (oneRingPositive(v)) return;
    }
    x.row(v) = start.row(v);
  }

  // The same for a sliding vertex, which must also stay inside its slide range, keep its gaps and
  // follow the outline. Whether a halving fits is close to monotone in the halving count (a smaller
  // slide leaves the vertex nearer its start, which fits); most vertices fit at the full slide, and
  // about one in four, pressed against a bound, at none (star-sequence, 16 keys). So the full slide
  // is tried, then the smallest, then the first fitting one is found by bisection: at most 7 tries
  // instead of 30.
  void slideVertex(int v, const Eigen::MatrixX2d& start, const Eigen::VectorXd& startU, double stepSize) {
    // A start that breaks a gap bound by more than a slide can move the vertex fails that slide
    // and every smaller one: only the halvings before the first such one are worth trying.
    const GapReach gap = gapReach(v, startU[v]);
    int tries = 0;
    while (tries < kHalvings && !gap.unrepairable(std::abs(std::ldexp(stepSize, -tries) * slide_[v]))) ++tries;
    double allowance = -1;  // of the start; found when a halving first passes the cheap tests (most that fail never do)
    // Places v at halving h; leaves it there if it fits, else back at its start.
    const auto fits = [&](int h) {
      const double u = startU[v] + std::ldexp(stepSize, -h) * slide_[v];
      const auto [lo, hi] = slideRange(v);
      if (!(u > lo && u < hi)) return false;
      mesh_.keys[key_].row(v) = mesh_.point(key_, mesh_.arc[v], u).transpose();
      mesh_.u(v, key_) = u;
      // The cheap tests first: the outline test walks the outline between the walk neighbours.
      if (keepsGap(v) && oneRingPositive(v)) {
        if (allowance < 0) allowance = outlineAllowance(v, startU[v]);
        if (followsOutline(v, allowance)) return true;
      }
      mesh_.keys[key_].row(v) = start.row(v);
      mesh_.u(v, key_) = startU[v];
      return false;
    };
    if (tries == 0 || fits(0) || tries == 1 || !fits(tries - 1)) return;
    int misses = 0, fitting = tries - 1;  // halving `misses` does not fit, `fitting` does
    bool placed = true;                   // v stands at `fitting`
    while (fitting - misses > 1) {
      const int middle = (misses + fitting) / 2;
      placed = fits(middle);
      (placed ? fitting : misses) = middle;
    }
    if (!placed) fits(fitting);
  }

  // Triangle c has positive area in key_.
  bool positive(const Triangle& c) const {
    const double* x = mesh_.keys[key_].col(0).data();
    const double* y = mesh_.keys[key_].col(1).data();
    return (x[c[1]] - x[c[0]]) * (y[c[2]] - y[c[0]]) - (x[c[2]] - x[c[0]]) * (y[c[1]] - y[c[0]]) > 0;
  }

  // A sliding vertex stays between `minimumGap_` and `maximumGap_` from its walk neighbours, so
  // that the boundary does not bunch up where the maps would like it infinitely dense (at corners
  // that map to straight outline the conformal optimum has no lower bound on spacing) nor thin out.
  bool keepsGap(int v) const { return gapViolation(v) <= 0; }

  // How far vertex v breaks those bounds at its current place (px; <= 0 when it keeps them).
  double gapViolation(int v) const {
    const Eigen::MatrixX2d& x = mesh_.keys[key_];
    const double before = (x.row(v) - x.row(mesh_.previous[v])).norm(), after = (x.row(v) - x.row(mesh_.next[v])).norm();
    return std::max({minimumGap_ - before, minimumGap_ - after, before - maximumGap_, after - maximumGap_});
  }

  // How far a sliding vertex, at its start, breaks the gap bounds of keepsGap (px; > 0 when it
  // does), and how far a slide of du can move it at most: the chord is no longer than the arc, plus
  // however far the start lies off the outline.
  struct GapReach {
    double violation = 0;    // px; <= 0 when the start keeps its gaps
    double arcLength = 0;    // px per unit u
    double offOutline = 0;   // px
    // True when no slide of at most du (fraction of the arc) can repair the violation (with slack
    // for rounding in the outline lookups, px).
    bool unrepairable(double du) const {
      return violation > 0 && arcLength > 0 && (du * arcLength + offOutline) * (1 + 1e-9) + 1e-9 < violation;
    }
  };
  GapReach gapReach(int v, double startU) const {
    GapReach r;
    r.violation = gapViolation(v);
    if (r.violation <= 0 || !mesh_.arcLength) return r;
    r.arcLength = mesh_.arcLength(key_, mesh_.arc[v]);
    r.offOutline = (mesh_.point(key_, mesh_.arc[v], startU).transpose() - mesh_.keys[key_].row(v)).norm();
    return r;
  }

  // How far a sliding vertex's boundary edges may stray from the outline (px): the tolerance, or
  // as far as they already do with the vertex at fraction u of its arc (its start).
  double outlineAllowance(int v, double u) const {
    if (!mesh_.chordDeviation) return 0;
    const auto [lo, hi] = slideRange(v);
    const int arc = mesh_.arc[v];
    return std::max(chordTolerance_, mesh_.chordDeviation(key_, arc, lo, u, hi));
  }

  // The boundary edges on either side of a sliding vertex, at its new place, stay within `allowance`.
  bool followsOutline(int v, double allowance) const {
    if (!mesh_.chordDeviation) return true;
    const auto [lo, hi] = slideRange(v);
    const int arc = mesh_.arc[v];
    const double now = mesh_.u(v, key_);
    return mesh_.chordDeviation(key_, arc, lo, now, hi) <= allowance;
  }

  bool oneRingPositive(int v) const {
    for (int t : mesh_.around[v])
      if (!positive(mesh_.triangles[t])) return false;
    return true;
  }

  ComeshMesh& mesh_;
  SobolevPreconditioner& preconditioner_;
  BlockEnergy& energy_;         // eq. 8's part that depends on key_, prepared for preparedVersion_
  int key_;
  double odtWeight_;
  long preparedVersion_ = -1;   // the mesh's topologyVersion when energy_ was prepared
  double minimumGap_, maximumGap_;  // px
  double chordTolerance_;  // px
  Eigen::MatrixX2d direction_;  // n x 2: descent direction per vertex (0 for fixed ones)
  Eigen::VectorXd slide_;       // n: descent direction in u for sliding vertices, else 0
};

int cohesiveCount(const Multimesh& mesh) {
  int count = 0;
  for (int k = 0; k < mesh.keyCount(); ++k) count += static_cast<int>(mesh.cohesivePairs(k).size());
  return count;
}

// Per key: balance x area / unit^2 (see ComeshOptions::odtBalance).
std::vector<double> balancedOdtWeights(const ComeshMesh& mesh, const Remesher& remesher, double balance) {
  std::vector<double> weights;
  for (int k = 0; k < mesh.keyCount(); ++k)
    weights.push_back(balance * totalArea(mesh.triangles, mesh.keys[k]) / std::pow(remesher.unitLength(k), 2));
  return weights;
}

// Triangles whose smallest angle is under 20 degrees, counted in every key.
int thinTriangles(const ComeshMesh& mesh) {
  std::vector<Triangle> live;
  std::copy_if(mesh.triangles.begin(), mesh.triangles.end(), std::back_inserter(live), [](const Triangle& t) { return t[0] >= 0; });
  int count = 0;
  for (const Eigen::MatrixX2d& x : mesh.keys) count += keyQuality(live, x).under20;
  return count;
}

}  // namespace

Multimesh comeshOptimize(const Multimesh& input, const ComeshBoundary* boundary, const ComeshOptions& options,
                         ComeshReport* report) {
  const auto started = std::chrono::steady_clock::now();
  ComeshMesh mesh(input, boundary);
  Remesher remesher(mesh, options.bounds);
  // Below a few thousand vertices a thread's share of a step is shorter than waking it.
  const int threads = mesh.vertexCount() < 4000 ? 1 : (options.threads > 0 ? options.threads : omp_get_max_threads());
  SobolevPreconditioner preconditioner(threads);
  BlockEnergy blockEnergy;
  blockEnergy.setThreads(threads);
  ThreadBudget budget(threads);  // how many of those threads to run now, asked again every step
  TeamScope team(budget);
  const std::vector<double> odtWeights = balancedOdtWeights(mesh, remesher, options.odtBalance);
  const int m = mesh.keyCount();
  std::vector<double> stepSize(m, 0.0);
  ComeshReport r;
  r.keys = m;
  r.verticesIn = input.vertexCount();
  r.trianglesIn = input.triangleCount();
  r.cohesiveIn = cohesiveCount(input);
  r.energyIn = comeshEnergy(mesh.triangles, mesh.keys, odtWeights);
  // The paper leaves sub_res open. It is the decrease of eq. 8 relative to its value when the sweep
  // over the keys starts, so that total_res is about the objective's relative decrease per sweep
  // and outer_tol means the same for any number of keys (relative to key i's part instead, each
  // key's share shrinks as 1 / m and 16 keys had to converge about 8 times tighter than 2).
  double objective = r.energyIn;
  int fewestThin = std::numeric_limits<int>::max(), stalled = 0;
  for (int outer = 0; outer < options.outerIterations; ++outer) {
    r.outerIterations = outer + 1;
    double total = 0;
    for (int i = 0; i < m; ++i) {
      const double unit = remesher.unitLength(i);
      VertexStepper stepper(mesh, preconditioner, blockEnergy, i, odtWeights[i],
                            {options.bounds.collapseLength * unit, options.bounds.splitLength * unit,
                             std::min(options.bounds.chordTolerance * unit, options.bounds.outlineTolerance)});
      double innerResidual = 0;
      for (int inner = 0; inner < options.innerIterations; ++inner) {
        ++r.innerIterations;
        team.update();
        if (options.remesh) {
          remesher.flipEdges(r.remesh);
          remesher.splitEdges(r.remesh);
        }
        const double residual = stepper.step(stepSize[i], objective);
        remesher.keyMoved(i);
        if (options.remesh) remesher.collapseEdges(r.remesh);
        innerResidual = std::max(innerResidual, residual);
        if (residual < options.innerTolerance) break;
      }
      total += innerResidual;
    }
    const double before = objective;
    objective = comeshEnergy(mesh.triangles, mesh.keys, odtWeights);
    if (options.progress) options.progress(outer + 1, objective);
    if (total < options.outerTolerance) break;
    if (options.sweepTolerance > 0) {
      const int thin = thinTriangles(mesh);
      const bool better = thin < fewestThin;
      fewestThin = std::min(fewestThin, thin);
      stalled = (!better && before - objective < options.sweepTolerance * before) ? stalled + 1 : 0;
      if (stalled >= options.sweepPatience) break;
    }
  }
  Multimesh out = mesh.toMultimesh();
  r.verticesOut = out.vertexCount();
  r.trianglesOut = out.triangleCount();
  r.cohesiveOut = cohesiveCount(out);
  r.energyOut = comeshEnergy(mesh.triangles, mesh.keys, odtWeights);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (report) *report = r;
  return out;
}

}  // namespace ib
