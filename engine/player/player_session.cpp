#include "player/player_session.h"

#include "core/error.h"
#include "multimesh/multimesh.h"
#include "playback/scene_parameters.h"

#include <map>

namespace ib::play {

namespace {

constexpr double kPollSeconds = 0.5;  // how often the scene's files are checked for changes

}  // namespace

PlayerSession::PlayerSession(std::unique_ptr<SceneReloader> reloader, const SolveWorker::Options& options)
    : reloader_(std::move(reloader)), options_(options) {
  rebuild(false);
}

PlayerSession::~PlayerSession() = default;

int PlayerSession::keyCount() const { return static_cast<int>(scene().scene.keys.size()); }

std::vector<std::string> PlayerSession::keyNames() const {
  std::vector<std::string> names;
  for (const KeySpec& key : scene().scene.keys) names.push_back(key.name);
  return names;
}

const Multimesh& PlayerSession::playedMesh() const {
  return initialMap_ && hasInitialMap() ? *scene().initial : *scene().mesh;
}

void PlayerSession::rebuild(bool keepParameters) {
  const LoadedScene& loaded = scene();
  std::map<std::string, double> tuned;  // what the user moved away from the old scene's values
  if (keepParameters && parameters_)
    for (const Control& c : parameters_->all())
      if (c.value != c.initial) tuned[c.spec->name] = c.value;
  if (!hasInitialMap()) initialMap_ = false;
  const std::shared_ptr<const Multimesh> played = initialMap_ ? loaded.initial : loaded.mesh;
  // The scene's multimesh comes with its render mesh, made off this thread; the initial map's is
  // made here (the user switched to it).
  renderMesh_ = initialMap_ ? playerRenderMesh(loaded.scene, *played, loaded.drawings, featureVertices(loaded.scene, *played))
                            : loaded.render;
  parameters_ = std::make_unique<LiveParameters>(loaded.scene);
  for (const auto& [name, value] : tuned) {
    try {
      parameters_->set(name, value);
    } catch (const InputError&) {  // out of the new scene's range: the scene's value stands
    }
  }
  const Timeline& timeline = loaded.scene.timeline;
  auto transport = std::make_unique<Transport>(timeline.frameCount(), timeline.fps());
  if (transport_) {
    transport->setLoop(transport_->loop());
    transport->setPingPong(transport_->pingPong());
    transport->setSpeed(transport_->speed());
    transport->goTo(transport_->frame());
    if (transport_->playing()) transport->play();
  }
  transport_ = std::move(transport);
  if (weights_.size() != keyCount()) {
    weights_ = Eigen::VectorXd::Zero(keyCount());
    weights_[0] = 1;
  }
  worker_.reset();  // its thread stops before the new one starts: the cores are the new one's
  const Scene live = parameters_->scene(loaded.scene);
  const SceneFrameSetup setup = sceneFrameSetup(live, *played, parameters_->frameOptions());
  worker_ = std::make_unique<SolveWorker>(played, setup.timeline, setup.interpolation, setup.dynamics, setup.stiffness, options_);
  sentGeneration_ = parameters_->generation();
  cutEvents_ = ib::cutEvents(live);
  requestedFrame_ = -1;
  if (weightsMode_) worker_->showWeights(weights_);
}

void PlayerSession::sendParameters() {
  const Scene tuned = parameters_->scene(scene().scene);
  const SceneFrameSetup setup = sceneFrameSetup(tuned, playedMesh(), parameters_->frameOptions());
  cutEvents_ = ib::cutEvents(tuned);
  worker_->setParameters(setup.interpolation, setup.dynamics, setup.stiffness);
  sentGeneration_ = parameters_->generation();
  requestedFrame_ = -1;  // re-solve what is shown
  if (weightsMode_) worker_->showWeights(weights_);
}

bool PlayerSession::update(double seconds) {
  bool meshChanged = false;
  sincePoll_ += seconds;
  if (sincePoll_ >= kPollSeconds) {
    sincePoll_ = 0;
    reloader_->poll();
  }
  if (reloader_->takeReloaded()) {
    rebuild(!adoptFileParameters_);
    adoptFileParameters_ = false;
    messages_.push_back({"reloaded " + scenePath(), false});
    meshChanged = true;
  }
  if (const std::optional<std::string> error = reloader_->takeError()) {
    messages_.push_back({"reload failed: " + *error + " (still playing the last good scene)", true});
    adoptFileParameters_ = false;
  }
  if (initialMapChanged_) {
    initialMapChanged_ = false;
    rebuild(true);
    meshChanged = true;
  }
  if (parameters_->generation() != sentGeneration_) sendParameters();
  // An edit's quick rebuild gets the cores the worker would spend on frames nobody asked for yet
  // (the slower builds run below the worker's priority and leave it be).
  worker_->setSolveAhead(!reloader_->previewing());
  if (!weightsMode_) {
    const int frame = transport_->advance(seconds);
    if (frame != requestedFrame_) {
      worker_->showFrame(frame);
      requestedFrame_ = frame;
    }
  }
  return meshChanged;
}

std::shared_ptr<const AnimationFrame> PlayerSession::shown() const {
  if (weightsMode_) return worker_->latest();
  if (std::shared_ptr<const AnimationFrame> frame = worker_->cached(transport_->frame())) return frame;
  return worker_->latest();
}

std::shared_ptr<const AnimationFrame> PlayerSession::cachedFrame(int index) const {
  if (index < 0 || index >= transport_->frameCount()) return nullptr;
  return worker_->cached(index);
}

void PlayerSession::setWeightsMode(bool on) {
  if (on == weightsMode_) return;
  weightsMode_ = on;
  requestedFrame_ = -1;
  if (on) {
    transport_->pause();
    worker_->showWeights(weights_);
  }
}

void PlayerSession::setWeights(const Eigen::VectorXd& weights) {
  if (weights.size() != keyCount())
    throw InputError("weights: " + std::to_string(weights.size()) + " given for " + std::to_string(keyCount()) + " keys");
  if ((weights.array() < 0).any() || !weights.allFinite()) throw InputError("weights: must be finite and not negative");
  const double sum = weights.sum();
  if (sum <= 0) throw InputError("weights: at least one must be positive");
  weights_ = weights / sum;
  if (weightsMode_) worker_->showWeights(weights_);
}

void PlayerSession::setInitialMap(bool on) {
  if (on == initialMap_ || (on && !hasInitialMap())) return;
  initialMap_ = on;
  initialMapChanged_ = true;
}

void PlayerSession::writeParameters() {
  if (parameterSaver_) parameterSaver_(*parameters_, transport_->fps());
  else play::saveParameters(scenePath(), *parameters_, transport_->fps());
  adoptFileParameters_ = true;
}

void PlayerSession::saveParameters() {
  try {
    writeParameters();
    messages_.push_back({"saved the parameters to " + scenePath(), false});
  } catch (const InputError& e) {
    messages_.push_back({std::string("saving failed: ") + e.what(), true});
  }
}

}  // namespace ib::play
