#include "animation/frame_stream.h"

#include "animation/even_spacing.h"
#include "animation/warm_start.h"
#include "core/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace ib {

namespace {

const Multimesh& matching(const Multimesh& mesh, const Timeline& timeline) {
  if (timeline.keyCount() != mesh.keyCount())
    throw std::invalid_argument("timeline: has weights for " + std::to_string(timeline.keyCount()) + " keys, the multimesh has " +
                     std::to_string(mesh.keyCount()));
  return mesh;
}

}  // namespace

AnimationFrame plainFrame(const Eigen::VectorXd& weights, const InterpolationResult& result) {
  AnimationFrame frame;
  frame.weights = weights;
  frame.x = result.x;
  frame.plain = result.x;
  frame.heldPairs = result.heldPairs;
  frame.iterations = result.iterations;
  frame.threads = result.threads;
  frame.converged = result.converged;
  frame.cancelled = result.cancelled;
  frame.milliseconds = result.milliseconds;
  return frame;
}

// Where a stream is and what its next frames depend on (a checkpoint's content).
struct StreamPosition {
  int next = 0;
  int shown = 0;                      // frames of the current run kept below (0, 1 or 2)
  Eigen::MatrixX2d last, beforeLast;  // x(s-1), x(s-2)
  double lastDeviation = 0;           // D(s-1)
  WarmStartPredictor predictor;
};

struct FrameStream::Checkpoint::Data {
  StreamPosition position;
  int vertices = 0, frames = 0;  // of the stream it was taken from
};

// Everything a stream carries from frame to frame.
struct FrameStream::State {
  State(const Multimesh& mesh, const Timeline& timeline, const InterpolationParams& params, const SolverOptions& options,
        const DynamicsParams& dynamics);
  AnimationFrame solveFrame(int index, double time, bool warm);
  void addDynamics(AnimationFrame& frame);
  // Builds what dynamics need (the second Interpolator, masses, anchor weights) if not yet built.
  void prepareDynamics();
  double deviation(const Eigen::MatrixX2d& x, const Eigen::MatrixX2d& plain) const;
  int frameCount() const { return timeline_.frameCount(); }
  double shapeSize() const { return plain_.shapeSize(); }

  Multimesh mesh_;  // kept for the anchor weights of new stiffness and a later second Interpolator
  Timeline timeline_;
  InterpolationParams params_;
  SolverOptions options_;
  DynamicsParams dynamics_;
  Interpolator plain_;
  std::optional<Interpolator> dynamic_;  // once dynamics are on: its own history and factorization
  const std::atomic<bool>* cancel_ = nullptr;
  Eigen::VectorXd mass_;    // m_v, summing to 1 (once dynamics are on)
  Eigen::VectorXd anchor_;  // a_v in (0, 1] (once dynamics are on)
  StreamPosition at_;
};

FrameStream::State::State(const Multimesh& mesh, const Timeline& timeline, const InterpolationParams& params,
                          const SolverOptions& options, const DynamicsParams& dynamics)
    : mesh_(mesh), timeline_(timeline), params_(params), options_(options), dynamics_(dynamics),
      plain_(matching(mesh, timeline), params, options) {
  validateDynamics(dynamics, "dynamics: ");
  // Segments with even spacing and no table yet get theirs from this stream's own solver (K
  // solves each, once); evenSpacing forgets the solver's history, so frame 0 is solved as fresh.
  if (needsEvenSpacing(timeline_)) timeline_ = evenSpacing(timeline_, plain_);
  if (dynamics.enabled()) prepareDynamics();
}

void FrameStream::State::prepareDynamics() {
  if (dynamic_) return;
  dynamic_.emplace(mesh_, params_, options_);
  dynamic_->setCancelFlag(cancel_);
  mass_ = lumpedMasses(mesh_);
  anchor_ = anchorWeights(mesh_);
}

FrameStream::FrameStream(const Multimesh& mesh, const Timeline& timeline, const InterpolationParams& params,
                         const SolverOptions& options, const DynamicsParams& dynamics)
    : state_(std::make_unique<State>(mesh, timeline, params, options, dynamics)) {}
FrameStream::~FrameStream() = default;
FrameStream::FrameStream(FrameStream&&) noexcept = default;
FrameStream& FrameStream::operator=(FrameStream&&) noexcept = default;

int FrameStream::frameCount() const { return state_->frameCount(); }
bool FrameStream::done() const { return state_->at_.next >= frameCount(); }
int FrameStream::nextFrame() const { return state_->at_.next; }
const Timeline& FrameStream::timeline() const { return state_->timeline_; }
const DynamicsParams& FrameStream::dynamics() const { return state_->dynamics_; }
double FrameStream::shapeSize() const { return state_->shapeSize(); }

void FrameStream::restart() {
  State& s = *state_;
  s.at_ = StreamPosition{};
  s.plain_.forgetHistory();
  if (s.dynamic_) s.dynamic_->forgetHistory();
}

AnimationFrame FrameStream::next() {
  if (done()) throw std::out_of_range("frame stream: all " + std::to_string(frameCount()) + " frames were taken");
  State& s = *state_;
  AnimationFrame frame = s.solveFrame(s.at_.next, s.timeline_.frameTime(s.at_.next), true);
  if (!frame.cancelled) ++s.at_.next;
  return frame;
}

void FrameStream::setParameters(const InterpolationParams& params, const DynamicsParams& dynamics) {
  State& s = *state_;
  validateDynamics(dynamics, "dynamics: ");
  s.plain_.setParameters(params);  // validates first; the same values cannot fail below
  s.params_ = params;
  if (s.dynamic_) s.dynamic_->setParameters(params);
  s.dynamics_ = dynamics;
  if (dynamics.enabled()) s.prepareDynamics();
}

void FrameStream::setStiffness(const Eigen::VectorXd& kappa) {
  State& s = *state_;
  s.plain_.setStiffness(kappa);  // validates first
  for (int t = 0; t < s.mesh_.triangleCount(); ++t) s.mesh_.setStiffness(t, kappa(t));
  if (s.dynamic_) {
    s.dynamic_->setStiffness(kappa);
    s.anchor_ = anchorWeights(s.mesh_);
  }
}

void FrameStream::setCancelFlag(const std::atomic<bool>* flag) {
  State& s = *state_;
  s.cancel_ = flag;
  s.plain_.setCancelFlag(flag);
  if (s.dynamic_) s.dynamic_->setCancelFlag(flag);
}

FrameStream::Checkpoint::Checkpoint() = default;
int FrameStream::Checkpoint::frame() const { return data_ ? data_->position.next : -1; }

FrameStream::Checkpoint FrameStream::checkpoint() const {
  auto data = std::make_shared<Checkpoint::Data>();
  data->position = state_->at_;
  data->vertices = state_->plain_.vertexCount();
  data->frames = frameCount();
  Checkpoint c;
  c.data_ = std::move(data);
  return c;
}

void FrameStream::resume(const Checkpoint& checkpoint) {
  State& s = *state_;
  if (!checkpoint.data_) throw std::invalid_argument("frame stream: resume from an empty checkpoint");
  if (checkpoint.data_->vertices != s.plain_.vertexCount() || checkpoint.data_->frames != frameCount())
    throw std::invalid_argument("frame stream: the checkpoint is of another multimesh or timeline");
  s.at_ = checkpoint.data_->position;
  s.plain_.forgetHistory();
  if (s.dynamic_) s.dynamic_->forgetHistory();
}

void FrameStream::seek(int frame, const AnimationFrame* neighbour) {
  State& s = *state_;
  if (s.dynamics_.enabled()) throw std::logic_error("frame stream: seek with dynamics; resume from a checkpoint");
  if (frame < 0 || frame > frameCount())
    throw std::out_of_range("frame stream: frame " + std::to_string(frame) + " is not in 0.." + std::to_string(frameCount()));
  s.at_ = StreamPosition{};
  s.at_.next = frame;
  if (neighbour) s.at_.predictor.remember(neighbour->weights, neighbour->plain);
}

AnimationFrame FrameStream::frameAt(double time) {
  if (!std::isfinite(time)) throw std::invalid_argument("frame time: must be a finite number of seconds");
  State& s = *state_;
  if (!s.dynamics_.enabled()) {
    const int index = static_cast<int>(std::floor((time - s.timeline_.start()) * s.timeline_.fps() + 1e-9));
    return s.solveFrame(index, time, false);
  }
  const double frames = std::floor((time - s.timeline_.start()) * s.timeline_.fps() + 1e-9);
  const int index = static_cast<int>(std::clamp(frames, 0.0, static_cast<double>(frameCount() - 1)));
  restart();
  AnimationFrame frame;
  while (s.at_.next <= index && !frame.cancelled) frame = next();
  return frame;
}

AnimationFrame FrameStream::State::solveFrame(int index, double time, bool warm) {
  const auto started = std::chrono::steady_clock::now();
  const Eigen::VectorXd weights = timeline_.weights(time);
  const std::optional<Eigen::MatrixX2d> start = warm ? at_.predictor.predict(weights) : std::nullopt;
  const InterpolationResult plain = plain_.solve(weights, start ? &*start : nullptr);
  AnimationFrame frame = plainFrame(weights, plain);
  frame.index = index;
  frame.time = time;
  if (warm && !frame.cancelled && dynamics_.enabled()) addDynamics(frame);
  // A cancelled frame changes nothing: the stream solves it again next.
  if (warm && !frame.cancelled) {
    at_.predictor.remember(frame.weights, plain.x);
    at_.beforeLast = std::move(at_.last);
    at_.last = frame.x;
    at_.shown = std::min(at_.shown + 1, 2);
    at_.lastDeviation = frame.deviation;
  }
  frame.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return frame;
}

// Eqs. 17-19 with the anchor, as one set of vertex springs: the minimizer of W_T + W_A alone is,
// per vertex, the spring target y_v = (c_T x_p + c_A xbar) / (c_T + c_A).
void FrameStream::State::addDynamics(AnimationFrame& frame) {
  const Timeline::Position position = timeline_.locate(frame.time);
  const int segments = static_cast<int>(timeline_.segments().size());
  frame.blend = at_.shown == 0 ? 0.0 : dynamicsBlend(dynamics_, position, segments, at_.lastDeviation);
  if (frame.blend == 0) return;
  const double h = 1 / timeline_.fps();
  const double size = shapeSize();
  const int n = static_cast<int>(mass_.size());
  const Eigen::MatrixX2d velocity =
      at_.shown >= 2 ? Eigen::MatrixX2d((at_.last - at_.beforeLast) / h) : Eigen::MatrixX2d::Zero(n, 2);
  const Eigen::RowVector2d acceleration = externalAcceleration(dynamics_, frame.time).transpose() * size;
  Eigen::MatrixX2d predicted = at_.last + h * std::exp(-dynamics_.mu * h) * velocity;  // x_p, eq. 17
  predicted.rowwise() += h * h * acceleration;
  // k_A per unit mass: a vertex of mean mass 1/n is anchored with `anchor` times the stiffness scale.
  const double anchorPerMass = dynamics_.anchor * dynamic_->stiffnessScale() * n;
  const double inertiaPerMass = anchorPerMass * frame.blend / (1 - frame.blend);  // xi / h^2
  frame.xi = inertiaPerMass * h * h;
  VertexSprings springs;
  springs.stiffness.resize(n);
  springs.target.resize(n, 2);
  for (int v = 0; v < n; ++v) {
    const double inertia = inertiaPerMass * mass_(v), anchor = anchorPerMass * anchor_(v) * mass_(v);
    springs.stiffness(v) = inertia + anchor;
    springs.target.row(v) = (inertia * predicted.row(v) + anchor * frame.plain.row(v)) / (inertia + anchor);
  }
  const InterpolationResult result = dynamic_->solve(frame.weights, &springs.target, &springs);
  frame.x = result.x;
  frame.heldPairs = result.heldPairs;
  frame.iterations += result.iterations;
  frame.threads = result.threads;
  frame.converged = frame.converged && result.converged;
  frame.cancelled = result.cancelled;
  frame.deviation = deviation(frame.x, frame.plain);
}

double FrameStream::State::deviation(const Eigen::MatrixX2d& x, const Eigen::MatrixX2d& plain) const {
  double sum = 0;
  for (Eigen::Index v = 0; v < x.rows(); ++v) sum += mass_(v) * (x.row(v) - plain.row(v)).squaredNorm();
  return std::sqrt(sum) / shapeSize();
}

}  // namespace ib
