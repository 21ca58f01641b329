#include "interpolation/interpolator_impl.h"

#include "core/error.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <omp.h>
#include <stdexcept>

namespace ib {

namespace {

std::vector<std::pair<int, int>> meshEdges(const Multimesh& mesh) {
  std::vector<std::pair<int, int>> edges;
  for (const auto& [a, b] : mesh.edges()) edges.push_back({a, b});
  return edges;
}

const Multimesh& validated(const Multimesh& mesh) {
  mesh.validate();
  validateStiffness(mesh.stiffnesses(), mesh.triangleCount());  // the range H's factorization holds
  return mesh;
}

void require(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) throw InputError("solver option " + field + ": " + rule);
}

const SolverOptions& validOptions(const InterpolationParams& p, const SolverOptions& o) {
  validateInterpolationParams(p);
  require(o.relativeTolerance > 0 && o.relativeTolerance < 1, "relativeTolerance", "must be in (0, 1)");
  require(o.keyTolerance > 0 && o.keyTolerance < 1, "keyTolerance", "must be in (0, 1)");
  require(o.keyReach > 0 && std::isfinite(o.keyReach), "keyReach", "must be > 0");
  require(o.maxIterations >= 1, "maxIterations", "must be >= 1");
  require(o.andersonDepth >= 0 && o.andersonDepth <= AndersonAcceleration::kMaxDepth, "andersonDepth",
          "must be in [0, " + std::to_string(AndersonAcceleration::kMaxDepth) + "]");
  require(o.refactorDistance >= 0 && std::isfinite(o.refactorDistance), "refactorDistance", "must be >= 0");
  require(o.staleHeldIterations >= 1, "staleHeldIterations", "must be >= 1");
  require(o.slowFrameIterations >= 0, "slowFrameIterations", "must be >= 0 (0 = never)");
  require(o.placementStiffness > 0 && std::isfinite(o.placementStiffness), "placementStiffness", "must be > 0");
  require(o.nonOverlapStiffness > 0 && std::isfinite(o.nonOverlapStiffness), "nonOverlapStiffness", "must be > 0");
  require(o.threads >= 0, "threads", "must be >= 0 (0 = all cores)");
  return o;
}

// Threads for a mesh of n vertices: below a few thousand vertices a thread's share of an
// iteration is shorter than the cost of waking it, so small meshes run on one.
int threadsFor(int requested, int vertices) {
  if (vertices < 4000) return 1;
  return requested > 0 ? requested : omp_get_max_threads();
}

}  // namespace

void validateWeights(const Eigen::VectorXd& w, int keyCount) {
  if (w.size() != keyCount)
    throw std::invalid_argument("weights: expected " + std::to_string(keyCount) + " values (one per key), got " +
                     std::to_string(w.size()));
  for (int i = 0; i < w.size(); ++i) {
    if (!std::isfinite(w(i))) throw std::invalid_argument("weights: w[" + std::to_string(i) + "] is not a finite number");
    if (w(i) < 0) throw std::invalid_argument("weights: w[" + std::to_string(i) + "] = " + std::to_string(w(i)) + " is negative");
  }
  if (std::abs(w.sum() - 1.0) > 1e-6)
    throw std::invalid_argument("weights: sum to " + std::to_string(w.sum()) + ", must sum to 1");
}

double Interpolator::Impl::gradientNorm(const Eigen::MatrixX2d& g) const {
  const int blocks = vertexSplit_.threads();
  std::vector<double> partial(static_cast<size_t>(blocks), 0.0);
  const double* gx = g.col(0).data();
  const double* gy = g.col(1).data();
#pragma omp parallel num_threads(teamFor(blocks))
  for (int p = omp_get_thread_num(); p < blocks; p += omp_get_num_threads()) {
    double largest = 0;
#pragma omp simd reduction(max : largest)
    for (int v = vertexSplit_.begin(p); v < vertexSplit_.end(p); ++v)
      largest = std::max(largest, std::max(std::abs(gx[v]), std::abs(gy[v])));
    partial[p] = largest;
  }
  return *std::max_element(partial.begin(), partial.end());
}

Interpolator::Impl::Impl(const Multimesh& mesh, const InterpolationParams& params, const SolverOptions& options)
    : Impl(threadLayout(validated(mesh), threadsFor(validOptions(params, options).threads, mesh.vertexCount())),
                   params, options) {}

Interpolator::Impl::Impl(ThreadLayout layout, const InterpolationParams& params, const SolverOptions& options)
    : params_(params),
      options_(options),
      originalOf_(std::move(layout.originalOf)),
      triangleOriginalOf_(std::move(layout.triangleOriginalOf)),
      vertexSplit_(std::move(layout.vertices)),
      triangleSplit_(std::move(layout.triangleSplit)),
      groups_(layout.mesh.vertexCount(), meshEdges(layout.mesh)),
      anderson_(options.andersonDepth, vertexSplit_.threads()),
      budget_(vertexSplit_.threads(), options.adaptThreads) {
  const Multimesh& mesh = layout.mesh;
  anderson_.setRowSplit(vertexSplit_, 2);  // the x and y columns of an n x 2 matrix
  const std::vector<Triangle>& triangles = layout.triangles;
  double meanArea = 0;
  for (int i = 0; i < mesh.keyCount(); ++i) {
    keys_.push_back(mesh.keyPositions(i));
    for (const Triangle& t : triangles)
      meanArea += signedArea(keys_[i].row(t[0]), keys_[i].row(t[1]), keys_[i].row(t[2])) / mesh.keyCount();
  }
  scale_ = std::sqrt(meanArea);
  for (auto& X : keys_) X /= scale_;
  deformation_ = std::make_unique<DeformationEnergy>(triangles, keys_, layout.kappa);
  // The same weight for every vertex (the normalized area, 1, shared out): it must not change
  // from frame to frame, or the rigid part of the carried Anderson history goes stale (measured:
  // about 15% more iterations with area weights blended by w), and it must not depend on keys
  // with zero weight.
  vertexWeight_ = 1.0 / mesh.vertexCount();
  updatePlacementWeights();
  cohesive_ = std::make_unique<CohesiveEnergy>(mesh, keys_, params.cohesive);
  checkCutTimings(params);
  gapPull_ = std::make_unique<GapPull>(mesh, keys_, *cohesive_, params.cohesive);
  nonOverlap_ = std::make_unique<NonOverlap>(mesh, 0.0);  // its penalty follows the stiffness scale
  updateStiffnessScale();
  global_ = std::make_unique<GlobalMatrix>(matrixSources(), mesh.vertexCount(), std::move(layout.partStart),
                                           vertexSplit_.threads());
}

void Interpolator::Impl::updateStiffnessScale() {
  // Mean diagonal of the ARAP matrix at uniform weights: the stiffness scale of one vertex.
  const Eigen::VectorXd uniform = Eigen::VectorXd::Constant(keyCount(), 1.0 / keyCount());
  const ActiveKeys all = activeKeys(uniform);
  double diagonal = 0;
  for (int t = 0; t < deformation_->triangleCount(); ++t)
    diagonal += deformation_->metric(t, all).sum();  // sum of E^T M E's diagonal = sum of M's entries
  diagonal /= vertexCount();
  stiffnessScale_ = diagonal;
  gradientFloor_ = 1e-13 * diagonal;
  nonOverlap_->setStiffness(options_.nonOverlapStiffness * diagonal);
}

void Interpolator::Impl::updatePlacementWeights() {
  if (params_.placement == Placement::kBlend) {
    placementWeight_.resize(0);
    placementTie_.resize(0);
    return;
  }
  placementWeight_ = stillnessWeights(keys_, 1.0 / scale_);  // keys_ are in shape sizes
  placementTie_ = options_.placementStiffness * placementWeight_;
}

GlobalMatrixSources Interpolator::Impl::matrixSources() const {
  GlobalMatrixSources sources{deformation_.get(), cohesive_.get(), nonOverlap_.get(),
                              options_.placementStiffness * vertexWeight_, stiffnessScale_};
  if (placementTie_.size()) sources.ties = &placementTie_;
  sources.gapPull = gapPull_.get();
  sources.enforceNonOverlap = params_.nonOverlap;
  return sources;
}

Interpolator::Impl::Frame Interpolator::Impl::makeFrame(const Eigen::VectorXd& w, const VertexSprings* springs) const {
  validateWeights(w, keyCount());
  Frame f;
  f.w = w;
  if (springs) {
    const int n = vertexCount();
    if (springs->stiffness.size() != n || springs->target.rows() != n)
      throw std::invalid_argument("vertex springs: expected " + std::to_string(n) + " stiffnesses and targets");
    if (!springs->target.allFinite() || !springs->stiffness.allFinite() || springs->stiffness.minCoeff() < 0)
      throw std::invalid_argument("vertex springs: stiffnesses must be finite and >= 0, targets finite");
    if (springs->stiffness.maxCoeff() > 0) {
      f.springs.resize(n);
      for (int k = 0; k < n; ++k) f.springs(k) = springs->stiffness(originalOf_[k]);
      f.springTarget = toLayout(springs->target, originalOf_) / scale_;
    }
  }
  f.keys = activeKeys(w);
  f.blend = Eigen::MatrixX2d::Zero(vertexCount(), 2);
  for (size_t a = 0; a < f.keys.index.size(); ++a) f.blend += f.keys.weight[a] * keys_[f.keys.index[a]];
  f.participants = nonOverlap_->participants(f.keys);
  return f;
}

double Interpolator::Impl::toleranceAt(const Eigen::VectorXd& w) const {
  double nearest = INFINITY;  // L1 distance to the nearest e_i: 2 (1 - w_i) for weights summing to 1
  for (Eigen::Index i = 0; i < w.size(); ++i) nearest = std::min(nearest, (w - Eigen::VectorXd::Unit(w.size(), i)).lpNorm<1>());
  const double t = std::clamp(nearest / options_.keyReach, 0.0, 1.0);
  const double key = std::min(options_.keyTolerance, options_.relativeTolerance);
  return key + t * (options_.relativeTolerance - key);
}

InterpolationResult Interpolator::Impl::solve(const Eigen::VectorXd& w, const Eigen::MatrixX2d* warmStart,
                                        const VertexSprings* springs) {
  const auto started = std::chrono::steady_clock::now();
  TeamScope team(budget_);  // the threads this solve runs on, asked again every iteration
  const Frame frame = makeFrame(w, springs);
  // CutTiming::kTau: pairs let go by earlier frames stay apart unless the weights turned back; a
  // solve from the blend (no warm start) is a fresh start, where nothing let go before.
  if (warmStart) cohesive_->holdAgain(frame.w);
  else cohesive_->forgetLetGo();
  State s;
  if (warmStart) {
    if (warmStart->rows() != vertexCount() || !warmStart->allFinite())
      throw std::invalid_argument("warm start: expected " + std::to_string(vertexCount()) + " finite positions");
    s.x = toLayout(*warmStart, originalOf_) / scale_;
  } else {
    s.x = frame.blend;
  }
  // Place the start rigidly with the groups its own links define (springs hold the rigid motions
  // themselves), take the cuts' neighbourhood rotations for the gap pull, then evaluate.
  if (!frame.springs.size()) {
    evaluateLinks(frame, s);
    align(frame, s, s.x);
  }
  gapPull_->freezeRotations(frame.blend);
  evaluateState(frame, s);

  InterpolationResult result;
  result.evaluations = 1;
  ensureFactorization(frame.w, frame.springs, s.held, result);
  result.startEnergy = s.energy;
  result.energyHistory.push_back(s.energy);
  const double startNorm = gradientNorm(s.gradient);
  // The fixed-point map of this frame is close to the last one's (it moves continuously with w,
  // also where a weight reaches or leaves zero), so the secant history seeds this frame. A
  // refactorized H changes the map more, but measurably less than dropping the history costs;
  // the safeguard rejects any step the stale history gets wrong.
  // At a non-overlap contact the map is discontinuous (W_O's targets jump as offenders come and
  // go) and the last frame's secants can lead into a cycle: circles-in-circles' frame 51 climbed
  // from E = 2.3e-3 to 7e-2 and back every 160 iterations, to the cap, where a fresh history
  // converges in 23. So a frame that starts in contact starts its history afresh.
  if (!s.contacts.empty()) anderson_.reset();
  else anderson_.restart();
  // Converged when the gradient fell by the relative tolerance, or reached the absolute floor
  // where it is rounding noise (a start that is already a minimizer). Near a key the solve goes
  // on towards the tighter target of toleranceAt while it still gains (a tenth of the gradient
  // within kPolish iterations): a start already close to the key can have too small a gradient
  // for that target to be reachable above rounding.
  const double converges = std::max(options_.relativeTolerance * startNorm, gradientFloor_);
  const double target = std::max(toleranceAt(w) * startNorm, gradientFloor_);
  constexpr int kPolish = 20;
  double polished = INFINITY;  // the smallest |g| since the rule was met
  int sincePolished = 0;
  double norm = startNorm;
  const auto relative = [&](double value) { return startNorm > 0 ? value / startNorm : 0.0; };
  result.residualHistory.push_back(relative(norm));

  State candidate;
  Eigen::MatrixX2d plain;
  int staleIterations = 0;  // accepted iterations in a row whose set of held pairs H does not model
  // With non-overlap, the plain steps taken at a contact (step()) may climb, and can cycle:
  // circles-in-circles' frame 24 went round a loop of 120 iterations, E within 6% above its
  // lowest, to the cap. So the lowest-energy iterate is kept, and once it has not improved (by a
  // part in 1e6) for kContactPatience iterations the solve goes back to it, with H at this frame's
  // weights, and from there takes descent steps only: it converges, or stops there.
  constexpr int kContactPatience = 40;
  State lowest;
  int sinceLowest = 0;
  contactSteps_ = true;
  bool stalledAtContact = false;
  if (params_.nonOverlap) lowest = s;
  bool touched = !s.contacts.empty();  // some iterate of this frame was at a non-overlap contact
  while (norm > target && result.iterations < options_.maxIterations) {
    if (cancelled()) {  // s is the last accepted iterate (away from contacts, the lowest energy so far)
      result.cancelled = true;
      break;
    }
    team.update();
    const Step outcome = step(frame, s, candidate, plain, result);
    if (outcome == Step::kRefactorized) continue;
    if (outcome == Step::kStalled) {  // no decrease along the step: not converged, unless at a contact's kink
      if (params_.nonOverlap && contactSteps_ && lowest.energy < s.energy) {  // back to the lowest, descent only
        s = lowest;
        norm = gradientNorm(s.gradient);
        contactSteps_ = false;
        refactorize(frame.w, frame.springs, s.held, result);
        anderson_.reset();
        staleIterations = 0;
        continue;
      }
      stalledAtContact = params_.nonOverlap && (touched || !s.contacts.empty());
      break;
    }
    std::swap(s, candidate);
    touched = touched || !s.contacts.empty();
    if (params_.nonOverlap && contactSteps_) {
      if (s.energy < lowest.energy * (1 - 1e-6)) {
        lowest = s;
        sinceLowest = 0;
      } else if (touched && ++sinceLowest >= kContactPatience) {
        if (s.energy > lowest.energy) s = lowest;
        contactSteps_ = false;
        refactorize(frame.w, frame.springs, s.held, result);
        anderson_.reset();
        staleIterations = 0;
      }
    }
    // A pair that let go keeps its stiff spring in a stale H, so steps along it stay tiny while
    // still lowering the energy, and nothing fails (measured: the frame where a cut lets go took
    // 46-500 iterations). So H's factor follows the pairs at once where it can (followHeld);
    // where that costs more than a factorization, H is rebuilt once it has been stale for a
    // while; at once would cost a factorization per iteration while pairs let go one after another.
    if (s.held != global_->held() && followHeld(frame.w, frame.springs, s.held, result)) anderson_.reset();
    staleIterations = s.held == global_->held() ? 0 : staleIterations + 1;
    if (staleIterations >= options_.staleHeldIterations) {
      refactorize(frame.w, frame.springs, s.held, result);
      anderson_.reset();
      staleIterations = 0;
    }
    ++result.iterations;
    // A slow frame under an H of other weights: H at this frame's weights, once.
    if (result.iterations == options_.slowFrameIterations && !global_->models({frame.w, frame.springs, s.held}, 0.0)) {
      refactorize(frame.w, frame.springs, s.held, result);
      anderson_.reset();
    }
    result.energyHistory.push_back(s.energy);
    norm = gradientNorm(s.gradient);
    result.residualHistory.push_back(relative(norm));
    if (norm <= converges) {
      if (norm < 0.9 * polished) {
        polished = norm;
        sincePolished = 0;
      } else if (++sincePolished >= kPolish) {
        break;
      }
    }
  }

  if (params_.nonOverlap) nonOverlap_->project(s.x, frame.participants);
  if (!s.x.allFinite()) throw std::runtime_error("interpolation produced non-finite positions");
  // With non-overlap the energy has a kink where the pieces touch (W_O acts on one side only), and
  // its gradient need not vanish at the minimum: a solve that finds no descent from its lowest
  // iterate has reached it, if the gradient there is within 10 times the rule (circles-in-circles'
  // frame 24: 1.2 times).
  result.threads = std::min(threads(), team.threads());
  result.converged = norm <= converges || (stalledAtContact && norm <= 10 * converges);
  result.relativeResidual = relative(norm);
  result.energy = s.energy;
  // The pairs that glue (under CutTiming::kRelease the ones whose closing pull is whole: a pair
  // fading out over the release window is still a spring in H, but its sides are parting).
  result.heldPairs = s.held;
  if (!result.cancelled) cohesive_->letGo(s.held, frame.w);
  if (params_.cohesive.timing == CutTiming::kRelease)
    for (size_t j = 0; j < result.heldPairs.size(); ++j)
      result.heldPairs[j] = result.heldPairs[j] && cohesive_->glued(static_cast<int>(j), frame.w);
  result.interpolationEnergy = s.energy - s.placement;
  result.x = fromLayout(s.x, originalOf_) * scale_;
  result.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return result;
}

Interpolator::Interpolator(const Multimesh& mesh, const InterpolationParams& params, const SolverOptions& options)
    : impl_(std::make_unique<Impl>(mesh, params, options)) {}
Interpolator::~Interpolator() = default;
Interpolator::Interpolator(Interpolator&&) noexcept = default;
Interpolator& Interpolator::operator=(Interpolator&&) noexcept = default;

InterpolationResult Interpolator::solve(const Eigen::VectorXd& w, const Eigen::MatrixX2d* warmStart,
                                        const VertexSprings* springs) {
  return impl_->solve(w, warmStart, springs);
}
EnergyEvaluation Interpolator::evaluate(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const {
  return impl_->evaluate(x, w);
}
int Interpolator::countOverlaps(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w) const {
  return impl_->countOverlaps(x, w);
}
double Interpolator::shapeSize() const { return impl_->shapeSize(); }
double Interpolator::stiffnessScale() const { return impl_->stiffnessScale(); }
int Interpolator::keyCount() const { return impl_->keyCount(); }
int Interpolator::vertexCount() const { return impl_->vertexCount(); }
int Interpolator::threads() const { return impl_->threads(); }
int Interpolator::triangleCount() const { return impl_->triangleCount(); }
long Interpolator::factorNonZeros() const { return impl_->factorNonZeros(); }

}  // namespace ib
