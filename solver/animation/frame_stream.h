// The frame stream every front end uses (player, renderer, exporter): the timeline's frames in
// order, each solved with a warm start from the ones before, plus dynamics when the scene asks for
// them (dynamics.h). Deterministic: the same multimesh, timeline and parameters give bit-identical
// frames on every run, and after restart().
//
// Usage:
//   FrameStream stream(mesh, timeline, params, options, dynamics);
//   while (!stream.done()) show(stream.next());
#pragma once

#include "animation/dynamics.h"
#include "animation/timeline.h"
#include "interpolation/interpolator.h"

#include <Eigen/Core>
#include <atomic>
#include <memory>
#include <vector>

namespace ib {

struct AnimationFrame {
  int index = 0;            // frame number, 0 at the timeline's start
  double time = 0;          // s
  Eigen::VectorXd weights;  // w(s), m x 1
  Eigen::MatrixX2d x;       // n x 2, the frame in the multimesh's units
  Eigen::MatrixX2d plain;   // n x 2, the plain inbetween xbar(w(s)) (equal to x without dynamics)
  double blend = 0;         // the controller's beta (0: plain interpolation)
  double xi = 0;            // the paper's xi (eq. 18), in normalized units
  double deviation = 0;     // mass-weighted RMS of x - plain, in shape sizes
  std::vector<char> heldPairs;  // which cohesive pairs hold at x (InterpolationResult::heldPairs)
  int iterations = 0;       // solver iterations spent on this frame (plain and dynamic solves)
  int threads = 1;          // threads its last solve ran on (fewer than asked while other work keeps cores busy)
  bool converged = true;    // every solve of this frame met the stopping rule
  bool cancelled = false;   // a solve was cancelled (FrameStream::setCancelFlag): x is not a frame of the animation
  double milliseconds = 0;  // wall time of this frame's solves
};

// The frame of one plain solve at weights w (m x 1): x and plain the result's positions, its held
// pairs, iterations, convergence, cancellation and time; index 0 and time 0 for the caller to set.
AnimationFrame plainFrame(const Eigen::VectorXd& weights, const InterpolationResult& result);

class FrameStream {
 public:
  // Validates the parameters (InputError naming the field). The timeline's key count must match
  // the multimesh's. Segments asking for even spacing without a table get one here (evenSpacing,
  // even_spacing.h: K plain solves per segment with these parameters; setParameters keeps it).
  FrameStream(const Multimesh& mesh, const Timeline& timeline, const InterpolationParams& params,
              const SolverOptions& options, const DynamicsParams& dynamics);

  ~FrameStream();
  FrameStream(FrameStream&&) noexcept;
  FrameStream& operator=(FrameStream&&) noexcept;

  int frameCount() const;
  bool done() const;
  int nextFrame() const;  // index of the frame next() returns (frameCount() when done)
  // The next frame in order. Throws std::out_of_range when done(). A cancelled frame
  // (AnimationFrame::cancelled) leaves the stream where it was: next() solves that frame again.
  AnimationFrame next();
  // Back to frame 0, forgetting warm starts, solver history and dynamics state.
  void restart();

  // Live changes, from the next frame on, validated as the constructor validates (nothing
  // changes when they throw); neither rebuilds a thread layout, ordering or pattern (see
  // Interpolator::setParameters), except that a stream built without dynamics builds its second
  // Interpolator the first time dynamics are switched on. The frames already solved and the
  // dynamics state stay (the motion goes on from them); restart() or resume() to replay.
  void setParameters(const InterpolationParams& params, const DynamicsParams& dynamics);
  // Per-triangle stiffness (t x 1, the multimesh's triangle order; Interpolator::setStiffness's
  // checks); the anchor weights follow it.
  void setStiffness(const Eigen::VectorXd& kappa);
  // While *flag is true, the solve under way stops within one iteration (Interpolator::setCancelFlag)
  // and its frame comes back with cancelled = true; nullptr: never cancelled.
  void setCancelFlag(const std::atomic<bool>* flag);

  // The stream's position with everything the frames after it depend on: the warm-start
  // predictor and the dynamics state (the last two frames shown, the last deviation). Copies
  // share their data. Solver history (Anderson's, H's factor) is not kept: resume() forgets it,
  // so the frames after a resume equal the uninterrupted stream's within the solver's tolerance,
  // not bit for bit: about as far apart as either is from the exact frames, in proportion to
  // SolverOptions::relativeTolerance (square-arch-stretch, dynamics on, resumed at frame 12, over
  // the next 10 frames: at most 1.4e-3 shape sizes at the default 1e-3, where the uninterrupted
  // stream is itself 7e-4 from the frames solved to 1e-10; 1.2e-4 at 1e-4). A resume from the
  // same checkpoint repeats its frames bit for bit.
  class Checkpoint {
   public:
    Checkpoint();
    int frame() const;  // the frame next() returns after resume(); -1 for a default-constructed one

   private:
    friend class FrameStream;
    struct Data;
    std::shared_ptr<const Data> data_;
  };
  Checkpoint checkpoint() const;
  // Back (or forward) to a checkpoint of this stream (or of one of the same multimesh and
  // timeline). With other parameters than when it was taken, the motion goes on from its state
  // under the new ones. std::invalid_argument for an empty checkpoint or one of a stream with
  // another vertex or frame count.
  void resume(const Checkpoint& checkpoint);
  // Without dynamics only: positions the stream at `frame` (0 <= frame <= frameCount()) without
  // solving the frames between, its warm start the positions of `neighbour` when given (a frame
  // of this stream, e.g. the cached one next to `frame`), else the blend of the keys. A frame
  // without dynamics depends only on its weights, so next() then gives the frame the
  // uninterrupted stream gives within the solver's tolerance; except near a cohesive release,
  // where another start can reach the energy's other minimum (a seam open where the stream,
  // coming from a closed one, still holds it; frameAt's cold start has the same limit). With
  // dynamics std::logic_error: the motion depends on every frame before (use resume()).
  void seek(int frame, const AnimationFrame* neighbour = nullptr);
  // One frame at time s without the frames before it: plain interpolation from a cold start
  // (equal to the streamed frame within the solver's tolerance). With dynamics the motion depends
  // on every frame before, so the stream restarts and runs up to the last frame at or before s
  // (returned with that frame's time). Leaves the stream positioned after the returned frame
  // (before it when the frame comes back cancelled).
  AnimationFrame frameAt(double time);

  const Timeline& timeline() const;  // as played: with the even-spacing tables
  const DynamicsParams& dynamics() const;
  double shapeSize() const;  // s = sqrt(mean key area), in the multimesh's units

 private:
  struct State;  // frame_stream.cpp: the interpolators, warm starts and dynamics state
  std::unique_ptr<State> state_;
};

}  // namespace ib
