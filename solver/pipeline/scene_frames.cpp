#include "pipeline/scene_frames.h"

#include "core/error.h"
#include "pipeline/cut_timing.h"
#include "multimesh/multimesh.h"

#include <cmath>
#include <string>

namespace ib {

SceneFrameSetup sceneFrameSetup(const Scene& scene, const Multimesh& mesh, const FrameOptions& options) {
  if (mesh.keyCount() != static_cast<int>(scene.keys.size()))
    throw InputError(scene.file + ": the multimesh has " + std::to_string(mesh.keyCount()) + " keys, the scene " +
                     std::to_string(scene.keys.size()) + ": mesh the scene again (`inbetween mesh`)");
  if (!(std::isfinite(options.kappaScale) && options.kappaScale > 0))
    throw InputError("kappa_scale: " + std::to_string(options.kappaScale) + " is not a number > 0");
  SceneFrameSetup setup;
  setup.timeline = scene.timeline;
  setup.interpolation = scene.interpolation;
  setup.interpolation.cohesive.perTerm = cutReleases(scene, mesh);
  // Correspondence from the artwork places the shape by what stays still (interpolation_params.h).
  setup.interpolation.placement =
      scene.correspondence == OutlineCorrespondence::kArtwork ? Placement::kStill : Placement::kBlend;
  setup.dynamics = scene.dynamics;
  if (!options.dynamics) setup.dynamics.epsilon = 0;
  setup.stiffness = mesh.stiffnesses() * options.kappaScale;
  setup.solver = options.solver;
  return setup;
}

FrameStream sceneFrameStream(const Scene& scene, const Multimesh& mesh, const FrameOptions& options) {
  const SceneFrameSetup setup = sceneFrameSetup(scene, mesh, options);
  FrameStream stream(mesh, setup.timeline, setup.interpolation, setup.solver, setup.dynamics);
  if (options.kappaScale != 1) stream.setStiffness(setup.stiffness);
  return stream;
}

}  // namespace ib
