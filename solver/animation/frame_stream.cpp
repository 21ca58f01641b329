#include "animation/frame_stream.h"

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

// Everything a stream carries from frame to frame.
struct FrameStream::State {
  State(const Multimesh& mesh, const Timeline& timeline, const InterpolationParams& params, const SolverOptions& options,
        const DynamicsParams& dynamics);
  AnimationFrame solveFrame(int index, double time, bool warm);
  void addDynamics(AnimationFrame& frame);
  double deviation(const Eigen::MatrixX2d& x, const Eigen::MatrixX2d& plain) const;
  int frameCount() const { return timeline_.frameCount(); }
  double shapeSize() const { return plain_.shapeSize(); }

  Timeline timeline_;
  DynamicsParams dynamics_;
  Interpolator plain_;
  std::optional<Interpolator> dynamic_;  // with dynamics only: its own history and factorization
  WarmStartPredictor predictor_;
  Eigen::VectorXd mass_;    // m_v, summing to 1
  Eigen::VectorXd anchor_;  // a_v in (0, 1]
  int next_ = 0;
  int shown_ = 0;                      // frames of the current run kept below (0, 1 or 2)
  Eigen::MatrixX2d last_, beforeLast_;  // x(s-1), x(s-2)
  double lastDeviation_ = 0;           // D(s-1)
};

FrameStream::State::State(const Multimesh& mesh, const Timeline& timeline, const InterpolationParams& params,
                          const SolverOptions& options, const DynamicsParams& dynamics)
    : timeline_(timeline), dynamics_(dynamics), plain_(matching(mesh, timeline), params, options) {
  validateDynamics(dynamics, "dynamics: ");
  if (dynamics.enabled()) {
    dynamic_.emplace(mesh, params, options);
    mass_ = lumpedMasses(mesh);
    anchor_ = anchorWeights(mesh);
  }
}

FrameStream::FrameStream(const Multimesh& mesh, const Timeline& timeline, const InterpolationParams& params,
                         const SolverOptions& options, const DynamicsParams& dynamics)
    : state_(std::make_unique<State>(mesh, timeline, params, options, dynamics)) {}
FrameStream::~FrameStream() = default;
FrameStream::FrameStream(FrameStream&&) noexcept = default;
FrameStream& FrameStream::operator=(FrameStream&&) noexcept = default;

int FrameStream::frameCount() const { return state_->frameCount(); }
bool FrameStream::done() const { return state_->next_ >= frameCount(); }
const Timeline& FrameStream::timeline() const { return state_->timeline_; }
const DynamicsParams& FrameStream::dynamics() const { return state_->dynamics_; }
double FrameStream::shapeSize() const { return state_->shapeSize(); }

void FrameStream::restart() {
  State& s = *state_;
  s.next_ = 0;
  s.shown_ = 0;
  s.lastDeviation_ = 0;
  s.predictor_.clear();
  s.plain_.forgetHistory();
  if (s.dynamic_) s.dynamic_->forgetHistory();
}

AnimationFrame FrameStream::next() {
  if (done()) throw std::out_of_range("frame stream: all " + std::to_string(frameCount()) + " frames were taken");
  State& s = *state_;
  AnimationFrame frame = s.solveFrame(s.next_, s.timeline_.frameTime(s.next_), true);
  ++s.next_;
  return frame;
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
  while (s.next_ <= index) frame = next();
  return frame;
}

AnimationFrame FrameStream::State::solveFrame(int index, double time, bool warm) {
  const auto started = std::chrono::steady_clock::now();
  AnimationFrame frame;
  frame.index = index;
  frame.time = time;
  frame.weights = timeline_.weights(time);
  const std::optional<Eigen::MatrixX2d> start = warm ? predictor_.predict(frame.weights) : std::nullopt;
  const InterpolationResult plain = plain_.solve(frame.weights, start ? &*start : nullptr);
  frame.plain = plain.x;
  frame.x = plain.x;
  frame.heldPairs = plain.heldPairs;
  frame.iterations = plain.iterations;
  frame.converged = plain.converged;
  if (warm) {
    predictor_.remember(frame.weights, plain.x);
    if (dynamic_) addDynamics(frame);
    beforeLast_ = std::move(last_);
    last_ = frame.x;
    shown_ = std::min(shown_ + 1, 2);
    lastDeviation_ = frame.deviation;
  }
  frame.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return frame;
}

// Eqs. 17-19 with the anchor, as one set of vertex springs: the minimizer of W_T + W_A alone is,
// per vertex, the spring target y_v = (c_T x_p + c_A xbar) / (c_T + c_A).
void FrameStream::State::addDynamics(AnimationFrame& frame) {
  const Timeline::Position position = timeline_.locate(frame.time);
  const int segments = static_cast<int>(timeline_.segments().size());
  frame.blend = shown_ == 0 ? 0.0 : dynamicsBlend(dynamics_, position, segments, lastDeviation_);
  if (frame.blend == 0) return;
  const double h = 1 / timeline_.fps();
  const double size = shapeSize();
  const int n = static_cast<int>(mass_.size());
  const Eigen::MatrixX2d velocity = shown_ >= 2 ? Eigen::MatrixX2d((last_ - beforeLast_) / h) : Eigen::MatrixX2d::Zero(n, 2);
  const Eigen::RowVector2d acceleration = externalAcceleration(dynamics_, frame.time).transpose() * size;
  Eigen::MatrixX2d predicted = last_ + h * std::exp(-dynamics_.mu * h) * velocity;  // x_p, eq. 17
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
  frame.converged = frame.converged && result.converged;
  frame.deviation = deviation(frame.x, frame.plain);
}

double FrameStream::State::deviation(const Eigen::MatrixX2d& x, const Eigen::MatrixX2d& plain) const {
  double sum = 0;
  for (Eigen::Index v = 0; v < x.rows(); ++v) sum += mass_(v) * (x.row(v) - plain.row(v)).squaredNorm();
  return std::sqrt(sum) / shapeSize();
}

}  // namespace ib
