// How a scene becomes frames, in one place: render, export, play, the benchmarks and the test
// tools ask here for what the frame stream of a scene and its multimesh is made of, and for the
// stream itself. The scene's parameters are read from the Scene (overridden beforehand through
// its document: SceneDocument::setFromText, `--set NAME=VALUE`); what is not a scene field comes
// in FrameOptions.
#pragma once

#include "animation/frame_stream.h"
#include "interpolation/interpolator.h"
#include "scene/scene.h"

#include <Eigen/Core>

namespace ib {

struct FrameOptions {
  // The solver's settings (tolerance, iteration cap, threads: 0 = all cores, fewer while other
  // work keeps cores busy). Default SolverOptions{}.
  SolverOptions solver;
  // Multiplies every triangle's painted stiffness (the player's kappa_scale), > 0. Default 1.
  double kappaScale = 1;
  // Dynamics on as the scene asks; false plays plain interpolation (the player's dynamics
  // toggle off). Default true.
  bool dynamics = true;
};

// What a scene's frame stream is made of.
struct SceneFrameSetup {
  Timeline timeline;                  // the scene's
  InterpolationParams interpolation;  // the scene's "solver" fields
  DynamicsParams dynamics;            // the scene's "dynamics" (epsilon 0 when FrameOptions::dynamics is off)
  Eigen::VectorXd stiffness;          // t x 1: the multimesh's painted kappa times FrameOptions::kappaScale
  SolverOptions solver;
};

// The setup for `scene` on `mesh` (a multimesh of the scene: its key count). InputError naming
// the option for a bad FrameOptions value.
SceneFrameSetup sceneFrameSetup(const Scene& scene, const Multimesh& mesh, const FrameOptions& options = {});

// The scene's frame stream on `mesh`, from sceneFrameSetup.
FrameStream sceneFrameStream(const Scene& scene, const Multimesh& mesh, const FrameOptions& options = {});

}  // namespace ib
