#include "playback/solve_worker_impl.h"

#include "animation/dynamics.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace ib::play {

void SolveWorker::Impl::validate(const Multimesh& mesh, const Parameters& p) {
  validateInterpolationParams(p.interpolation);
  validateDynamics(p.dynamics, "dynamics: ");
  validateStiffness(p.kappa, mesh.triangleCount());
}

SolveWorker::Impl::Impl(std::shared_ptr<const Multimesh> mesh, Timeline timeline, Parameters parameters,
                        const Options& options)
    : mesh_(std::move(mesh)), timeline_(std::move(timeline)), options_(options), frameCount_(timeline_.frameCount()),
      solverOptions_(options.solver) {
  solverOptions_.threads = options.threads;
  pending_ = std::move(parameters);
  weights_ = Eigen::VectorXd::Zero(mesh_->keyCount());
  thread_ = std::thread([this] { run(); });
}

SolveWorker::Impl::~Impl() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    cancel_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void SolveWorker::Impl::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || (job = plan()).kind != Job::Kind::kNone; });
      if (stop_) return;
      if (job.kind == Job::Kind::kApply) pending_.reset();
      running_ = {job.kind, job.frame, job.wanted};
      cancel_ = false;
    }
    std::optional<AnimationFrame> frame;
    std::string error;
    try {
      if (job.kind == Job::Kind::kApply) {
        apply(job);
      } else {
        frame = solve(job);
      }
    } catch (const std::exception& e) {
      error = e.what();
    }
    record(job, std::move(frame), error);
  }
}

void SolveWorker::Impl::apply(const Job& job) {
  const Parameters& p = job.parameters;
  if (!stream_) {
    stream_.emplace(*mesh_, timeline_, p.interpolation, solverOptions_, p.dynamics);
    if (p.kappa != mesh_->stiffnesses()) stream_->setStiffness(p.kappa);
    stream_->setCancelFlag(&cancel_);
  } else {
    stream_->setParameters(p.interpolation, p.dynamics);
    stream_->setStiffness(p.kappa);
  }
  if (still_) {
    still_->setParameters(p.interpolation);
    still_->setStiffness(p.kappa);
  }
  // With dynamics the motion is replayed from frame 0, whose state depends on no parameter.
  if (p.dynamics.enabled()) stream_->restart();
  applied_ = p;
}

std::optional<AnimationFrame> SolveWorker::Impl::solve(const Job& job) {
  if (job.kind == Job::Kind::kStill) {
    if (!still_) {
      still_.emplace(*mesh_, applied_.interpolation, solverOptions_);
      if (applied_.kappa != mesh_->stiffnesses()) still_->setStiffness(applied_.kappa);
      still_->setCancelFlag(&cancel_);
    }
    const InterpolationResult r = still_->solve(job.weights, stillStart_.size() ? &stillStart_ : nullptr);
    stillStart_ = r.x;  // also when cancelled: the best iterate so far is the best start
    AnimationFrame f = plainFrame(job.weights, r);
    f.index = -1;
    return f;
  }
  if (job.resume) {
    if (job.checkpoint.frame() >= 0) {
      stream_->resume(job.checkpoint);
    } else {
      stream_->restart();
    }
  }
  if (job.seek) stream_->seek(job.frame, job.neighbour.get());
  if (dynamics_ && job.frame % options_.checkpointEvery == 0) {
    FrameStream::Checkpoint checkpoint = stream_->checkpoint();
    std::lock_guard<std::mutex> lock(mutex_);
    if (job.generation == generation_ && !pending_) checkpoints_.emplace(job.frame, std::move(checkpoint));
  }
  return stream_->next();
}

void SolveWorker::Impl::record(const Job& job, std::optional<AnimationFrame> frame, const std::string& error) {
  std::lock_guard<std::mutex> lock(mutex_);
  running_ = {};
  if (stream_) streamNext_ = stream_->nextFrame();
  const bool current = job.generation == generation_ && !pending_;
  if (job.kind == Job::Kind::kApply) {
    built_ = stream_.has_value();
    if (error.empty()) {
      dynamics_ = job.parameters.dynamics.enabled();
      ++stats_.parameterSets;
      stats_.error.clear();  // a fresh start: errors of the parameters before are gone with them
    }
    checkpoints_.clear();
    if (dynamics_ && built_) {
      if (stream_->nextFrame() != 0) stream_->restart();  // apply() failed before it restarted
      streamNext_ = 0;
      checkpoints_.emplace(0, stream_->checkpoint());
    }
    failed_.clear();
    stillDone_ = -1;
  }
  if (!error.empty()) {
    stats_.error = error;
    if (job.kind == Job::Kind::kFrame && current) failed_.insert(job.frame);
    if (job.kind == Job::Kind::kStill && current) stillDone_ = job.request;
  } else if (frame && !frame->cancelled && current) {
    auto shared = std::make_shared<const AnimationFrame>(std::move(*frame));
    stats_.solveMs = shared->milliseconds;
    stats_.iterations = shared->iterations;
    stats_.converged = shared->converged;
    stats_.deviation = shared->deviation;
    lastSolved_ = shared;
    // The picture moves on with every frame or still that is wanted, or was when its solve
    // began: a continuous scrub or drag shows each one solved on its way.
    if (job.kind == Job::Kind::kStill) {
      stillDone_ = std::max(stillDone_, job.request);
      if (weightsMode_) picture_ = shared;
    } else {
      ++stats_.framesSolved;
      insert(job.frame, shared);
      if (!weightsMode_ && (job.frame == wanted_ || (job.wanted && job.frame == job.target))) {
        const auto it = cache_.find(job.frame);  // the first solve of a frame solved twice
        picture_ = it != cache_.end() ? it->second : shared;
      }
    }
  }
  done_.notify_all();
}

void SolveWorker::Impl::cancelUnless(bool useful) {
  if (!useful && (running_.kind == Job::Kind::kFrame || running_.kind == Job::Kind::kStill)) cancel_ = true;
}

void SolveWorker::Impl::setParameters(Parameters parameters) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = std::move(parameters);
    ++generation_;
    cache_.clear();
    cancelUnless(false);
  }
  wake_.notify_all();
  done_.notify_all();
}

void SolveWorker::Impl::showFrame(int index) {
  if (index < 0 || index >= frameCount_)
    throw std::out_of_range("frame " + std::to_string(index) + " is not in 0.." + std::to_string(frameCount_ - 1));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool wasWeights = weightsMode_;
    weightsMode_ = false;
    wanted_ = index;
    if (running_.kind == Job::Kind::kFrame) {
      const bool onTheWay = dynamics_ ? running_.frame >= checkpointBelow(index) && running_.frame <= index
                                      : running_.frame == index;
      cancelUnless(running_.wanted || cache_.count(index) || onTheWay);
    } else {
      cancelUnless(!wasWeights);
    }
    if (auto it = cache_.find(index); it != cache_.end()) picture_ = it->second;
  }
  wake_.notify_all();
  done_.notify_all();
}

void SolveWorker::Impl::showWeights(const Eigen::VectorXd& w) {
  validateWeights(w, mesh_->keyCount());
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (weightsMode_ && w == weights_) return;  // the same still again (a UI calling every tick)
    weightsMode_ = true;
    weights_ = w;
    ++request_;
    cancelUnless(running_.kind == Job::Kind::kStill);
  }
  wake_.notify_all();
  done_.notify_all();
}

void SolveWorker::Impl::setSolveAhead(bool on) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (ahead_ == on) return;
    ahead_ = on;
    if (!on && running_.kind == Job::Kind::kFrame) cancelUnless(running_.wanted);
  }
  wake_.notify_all();
  done_.notify_all();
}

std::shared_ptr<const AnimationFrame> SolveWorker::Impl::latest() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!weightsMode_)
    if (auto it = cache_.find(wanted_); it != cache_.end()) return it->second;
  return picture_ ? picture_ : lastSolved_;
}

std::shared_ptr<const AnimationFrame> SolveWorker::Impl::cached(int index) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = cache_.find(index);
  return it == cache_.end() ? nullptr : it->second;
}

SolveWorker::Stats SolveWorker::Impl::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  Stats s = stats_;
  s.busy = running_.kind != Job::Kind::kNone || plan().kind != Job::Kind::kNone;
  s.parametersPending = pending_.has_value() || running_.kind == Job::Kind::kApply;
  s.cachedFrames = static_cast<int>(cache_.size());
  return s;
}

bool SolveWorker::Impl::waitIdle(double seconds) {
  std::unique_lock<std::mutex> lock(mutex_);
  return done_.wait_for(lock, std::chrono::duration<double>(std::max(seconds, 0.0)), [&] { return idle(); });
}

SolveWorker::SolveWorker(std::shared_ptr<const Multimesh> mesh, Timeline timeline, const InterpolationParams& interpolation,
                         const DynamicsParams& dynamics, const Eigen::VectorXd& kappa, const Options& options) {
  if (!mesh) throw std::invalid_argument("solve worker: no multimesh");
  if (timeline.keyCount() != mesh->keyCount())
    throw std::invalid_argument("solve worker: the timeline has weights for " + std::to_string(timeline.keyCount()) +
                                " keys, the multimesh has " + std::to_string(mesh->keyCount()));
  if (options.threads < 0) throw std::invalid_argument("solve worker: threads must be >= 0 (0 = all cores)");
  if (options.checkpointEvery < 1) throw std::invalid_argument("solve worker: checkpointEvery must be >= 1");
  if (options.cacheFrames < 1) throw std::invalid_argument("solve worker: cacheFrames must be >= 1");
  Impl::Parameters parameters{interpolation, dynamics, kappa};
  Impl::validate(*mesh, parameters);
  impl_ = std::make_unique<Impl>(std::move(mesh), std::move(timeline), std::move(parameters), options);
}

SolveWorker::~SolveWorker() = default;

void SolveWorker::setParameters(const InterpolationParams& interpolation, const DynamicsParams& dynamics,
                                const Eigen::VectorXd& kappa) {
  Impl::Parameters parameters{interpolation, dynamics, kappa};
  Impl::validate(impl_->mesh(), parameters);
  impl_->setParameters(std::move(parameters));
}
void SolveWorker::showFrame(int index) { impl_->showFrame(index); }
void SolveWorker::showWeights(const Eigen::VectorXd& w) { impl_->showWeights(w); }
void SolveWorker::setSolveAhead(bool on) { impl_->setSolveAhead(on); }
std::shared_ptr<const AnimationFrame> SolveWorker::latest() const { return impl_->latest(); }
std::shared_ptr<const AnimationFrame> SolveWorker::cached(int index) const { return impl_->cached(index); }
SolveWorker::Stats SolveWorker::stats() const { return impl_->stats(); }
bool SolveWorker::waitIdle(double seconds) { return impl_->waitIdle(seconds); }

}  // namespace ib::play
