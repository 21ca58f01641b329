// The model the player's window drives, CPU only: the scene (reloaded in the background), its
// render mesh, the live parameters, the transport, the solve worker, and weights mode. The window
// calls update() once per presented frame; nothing here waits for a solve.
#pragma once

#include "output/render_mesh.h"
#include "pipeline/cut_timing.h"
#include "playback/live_parameters.h"
#include "playback/scene_reloader.h"
#include "playback/solve_worker.h"
#include "playback/transport.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ib::play {

class PlayerSession {
 public:
  // Plays the reloader's current scene. `options`: the worker's threads, checkpoints and cache.
  PlayerSession(std::unique_ptr<SceneReloader> reloader, const SolveWorker::Options& options);
  ~PlayerSession();

  // One UI frame: swaps in a finished reload (true: the render mesh changed, the window must draw
  // the new one), resends changed parameters to the worker, advances the transport by `seconds`
  // of wall time and asks the worker for the frame to show. Errors (a failed reload) go to
  // messages(); the last good scene keeps playing.
  bool update(double seconds);

  const LoadedScene& scene() const { return reloader_->current(); }
  // Where each cut lets go and glues on the timeline, with the live parameters (the scrubber's marks).
  const std::vector<CutEvent>& cutEvents() const { return cutEvents_; }
  const std::string& scenePath() const { return reloader_->path(); }
  SceneReloader& reloader() { return *reloader_; }
  const render::RenderMesh& renderMesh() const { return *renderMesh_; }
  LiveParameters& parameters() { return *parameters_; }
  Transport& transport() { return *transport_; }
  SolveWorker& worker() { return *worker_; }
  int keyCount() const;
  std::vector<std::string> keyNames() const;

  // The frame to draw: in weights mode the worker's latest; else the transport's frame from the
  // cache, or the latest solved one while it is being solved. Null before the first solve.
  std::shared_ptr<const AnimationFrame> shown() const;
  // Timeline frame `index` if it is solved (onion skins), else null.
  std::shared_ptr<const AnimationFrame> cachedFrame(int index) const;

  // Weights mode: a still at convex weights instead of the timeline; off resumes the timeline.
  bool weightsMode() const { return weightsMode_; }
  void setWeightsMode(bool on);
  const Eigen::VectorXd& weights() const { return weights_; }
  // Non-negative, normalized to sum 1 (InputError for the wrong count, a negative or all zero).
  void setWeights(const Eigen::VectorXd& weights);

  // Plays the initial map instead of the Comesh-optimized multimesh, when the scene has both.
  bool hasInitialMap() const { return scene().initial && scene().initial != scene().mesh; }
  bool initialMap() const { return initialMap_; }
  void setInitialMap(bool on);  // takes effect in the next update() (which then returns true)

  // Errors and notices for the window, oldest first (a failed reload, a saved file).
  struct Message {
    std::string text;
    bool error = false;
  };
  std::vector<Message>& messages() { return messages_; }
  void saveParameters();   // into the scene file (scene_parameters.h), or the saver's; a failure goes to messages()
  void writeParameters();  // the same, throwing its InputError (a scripted run's --save)
  // Who saves the parameters instead of the scene file (the editor: into its document, then the
  // document into the file, so that the file and the document agree); null: the file. The saver
  // throws InputError for a failure.
  using ParameterSaver = std::function<void(LiveParameters& parameters, double fps)>;
  void setParameterSaver(ParameterSaver saver) { parameterSaver_ = std::move(saver); }

 private:
  void rebuild(bool keepParameters);  // render mesh, parameters, transport and worker of the current scene
  void sendParameters();
  const Multimesh& playedMesh() const;

  std::unique_ptr<SceneReloader> reloader_;
  SolveWorker::Options options_;
  std::shared_ptr<const render::RenderMesh> renderMesh_;  // the window's renderer copies what it draws
  std::unique_ptr<LiveParameters> parameters_;
  std::unique_ptr<Transport> transport_;
  std::unique_ptr<SolveWorker> worker_;
  int sentGeneration_ = -1;
  std::vector<CutEvent> cutEvents_;  // of the scene with the live parameters, as last sent
  bool weightsMode_ = false;
  Eigen::VectorXd weights_;
  bool initialMap_ = false, initialMapChanged_ = false;
  int requestedFrame_ = -1;
  std::vector<Message> messages_;
  double sincePoll_ = 0;            // s since the files were last checked for changes
  bool adoptFileParameters_ = false;  // after a save: the reloaded file holds the tuned values
  ParameterSaver parameterSaver_;
};

}  // namespace ib::play
