// The player's solve worker: one thread that solves what the player shows, so that the UI thread
// never waits for a solve. Every public method may be called from the UI thread at any time and
// returns at once (waitIdle and the destructor aside).
//
// Timeline mode (showFrame): frames are solved in order through a FrameStream (with dynamics a
// frame needs every frame before it) and cached. While nothing else is wanted the worker solves
// ahead of the shown frame, wrapping on a looping timeline, so playback finds its frames ready.
// An uncached frame is reached from the nearest dynamics checkpoint at or before it (one every
// Options::checkpointEvery frames), or, without dynamics, solved directly, warm from a cached
// neighbour when there is one. Weights mode (showWeights): a still at weights w from an
// Interpolator of its own, warm from its last still.
//
// Cancelling: new parameters cancel the solve under way at once (within one iteration); so does
// a switch between the modes, and a new frame wanted while the worker solves ahead along another
// way. A solve for a frame that was wanted (or on the way to it), or for a still, runs to its end
// when the wanted frame or weights change again: a continuous scrub or drag shows a new picture
// after every solve instead of cancelling each one. Frames are solved one at a time and what to
// solve next is chosen afresh after each, so the newest request is served next.
//
// The worker waits on a condition variable when there is nothing to do; it never spins. A solve
// that throws leaves its message in Stats::error, the last good picture stays and that frame is
// not tried again until the parameters change.
#pragma once

#include "animation/frame_stream.h"
#include "animation/timeline.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <memory>
#include <string>

namespace ib::play {

class SolveWorker {
 public:
  struct Options {
    // The most solver threads; 0 = all cores. The solver runs fewer while the window's drawing or
    // other programs keep cores busy (core/thread_budget.h). Default 0.
    int threads = 0;
    int checkpointEvery = 12;  // frames between dynamics checkpoints kept for scrubbing backwards, >= 1
    int cacheFrames = 2000;    // solved frames kept (the timeline's frames are cached for instant scrubbing), >= 1
    // The solver's settings (tolerance, iteration cap, ...); its `threads` is replaced by the
    // one above. Default SolverOptions{}.
    SolverOptions solver;
  };
  struct Stats {
    bool busy = false;          // a solve is running or queued
    double solveMs = 0;         // wall time of the last finished solve (ms)
    int iterations = 0;         // its iterations
    bool converged = true;      // it met the stopping rule
    double deviation = 0;       // its dynamics deviation (AnimationFrame::deviation)
    int cachedFrames = 0;
    std::string error;          // the last solver error (empty: none; cleared when new parameters apply); the worker keeps running
    long framesSolved = 0;      // timeline frames solved since the start, the ones on the way to a wanted frame included
    long parameterSets = 0;     // parameter sets applied since the start, the constructor's included (coalesced ones are skipped)
    bool parametersPending = false;  // a set given to setParameters is not applied yet (nor skipped for a newer one)
  };

  // Starts the worker thread. kappa: per-triangle painted stiffness times the kappa scale (t x 1).
  // The parameters are checked here (InputError naming the field; std::invalid_argument for a
  // wrong size or a bad option); the solvers are built on the worker thread, so construction does
  // not wait for them either.
  SolveWorker(std::shared_ptr<const Multimesh> mesh, Timeline timeline, const InterpolationParams& interpolation,
              const DynamicsParams& dynamics, const Eigen::VectorXd& kappa, const Options& options);
  ~SolveWorker();  // cancels and joins
  SolveWorker(const SolveWorker&) = delete;
  SolveWorker& operator=(const SolveWorker&) = delete;

  // Coalesced (the newest wins): cancels a solve in progress, clears the cache; frames are solved
  // again from the frame shown (never rebuilds the thread layout, orderings or patterns). Checked
  // as the constructor checks them, on the calling thread: nothing changes when it throws. With
  // dynamics the motion is replayed from frame 0 up to the frame shown (exactly the animation
  // these parameters give); until the frame shown is solved, latest() keeps the old picture.
  void setParameters(const InterpolationParams& interpolation, const DynamicsParams& dynamics, const Eigen::VectorXd& kappa);
  // Timeline mode: the frame wanted next, 0 <= index < the timeline's frame count (std::out_of_range otherwise).
  void showFrame(int index);
  // Weights mode: a still at weights w (convex, m x 1; std::invalid_argument otherwise).
  void showWeights(const Eigen::VectorXd& w);
  // Timeline mode solves ahead of the wanted frame while idle (on: the default). Off while other
  // work needs the cores more (the editor's rebuild after an edit): only wanted frames are solved,
  // and a solve ahead under way is cancelled. Cheap when it does not change.
  void setSolveAhead(bool on);

  // Non-blocking, never null once anything is solved: the wanted frame if solved, else the most
  // recently solved frame (or still) that was wanted when its solve began (else the most recently
  // solved one), so the picture never goes blank while a solve runs, follows a continuous scrub
  // or drag, and does not run through the frames on the way to the one wanted. A still has
  // index -1 and time 0.
  std::shared_ptr<const AnimationFrame> latest() const;
  std::shared_ptr<const AnimationFrame> cached(int index) const;  // null when not (yet) solved
  Stats stats() const;
  // Blocks until the wanted frame (or weights) is solved with the newest parameters, or its solve
  // failed (Stats::error); false after `seconds`.
  bool waitIdle(double seconds);

 private:
  class Impl;  // solve_worker.cpp
  std::unique_ptr<Impl> impl_;
};

}  // namespace ib::play
