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
  bool converged = true;    // every solve of this frame met the stopping rule
  double milliseconds = 0;  // wall time of this frame's solves
};

class FrameStream {
 public:
  // Validates the parameters (InputError naming the field). The timeline's key count must match
  // the multimesh's.
  FrameStream(const Multimesh& mesh, const Timeline& timeline, const InterpolationParams& params,
              const SolverOptions& options, const DynamicsParams& dynamics);

  ~FrameStream();
  FrameStream(FrameStream&&) noexcept;
  FrameStream& operator=(FrameStream&&) noexcept;

  int frameCount() const;
  bool done() const;
  // The next frame in order. Throws std::out_of_range when done().
  AnimationFrame next();
  // Back to frame 0, forgetting warm starts, solver history and dynamics state.
  void restart();
  // One frame at time s without the frames before it: plain interpolation from a cold start
  // (equal to the streamed frame within the solver's tolerance). With dynamics the motion depends
  // on every frame before, so the stream restarts and runs up to the last frame at or before s
  // (returned with that frame's time). Leaves the stream positioned after the returned frame.
  AnimationFrame frameAt(double time);

  const Timeline& timeline() const;
  const DynamicsParams& dynamics() const;
  double shapeSize() const;  // s = sqrt(mean key area), in the multimesh's units

 private:
  struct State;  // frame_stream.cpp: the interpolators, warm starts and dynamics state
  std::unique_ptr<State> state_;
};

}  // namespace ib
