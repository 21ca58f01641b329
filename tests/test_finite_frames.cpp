// The solver never hands out a NaN or infinite frame: at the far ends of every range the scene
// and the player accept (huge gravity, wind, cohesion and stiffness, tiny tau), every frame of a
// scene with dynamics is finite. A step that produces non-finite values is rejected (its energy
// is not finite), so a solve that cannot make progress stops at its last finite iterate and
// reports that it did not converge.
#include "animation/frame_stream.h"
#include "core/error.h"
#include "meshing/multimesh_builder.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>

#include <string>

using namespace ib;

namespace {

struct Extreme {
  std::string name;
  void (*apply)(InterpolationParams&, DynamicsParams&, Eigen::VectorXd& kappa);
};

}  // namespace

TEST_CASE("solver: every frame of a scene with dynamics is finite at the far ends of every accepted parameter") {
  const std::vector<Extreme> extremes = {
      {"gravity 1e300", [](InterpolationParams&, DynamicsParams& d, Eigen::VectorXd&) { d.gravity = {0, 1e300}; }},
      {"wind -1e300", [](InterpolationParams&, DynamicsParams& d, Eigen::VectorXd&) { d.wind = {-1e300, 0}; }},
      {"mu 1e300", [](InterpolationParams&, DynamicsParams& d, Eigen::VectorXd&) { d.mu = 1e300; }},
      {"anchor 1e-300", [](InterpolationParams&, DynamicsParams& d, Eigen::VectorXd&) { d.anchor = 1e-300; }},
      {"anchor 1e300", [](InterpolationParams&, DynamicsParams& d, Eigen::VectorXd&) { d.anchor = 1e300; }},
      {"lambda 1e300", [](InterpolationParams& p, DynamicsParams&, Eigen::VectorXd&) { p.cohesive.lambda = 1e300; }},
      {"tau 1e-300", [](InterpolationParams& p, DynamicsParams&, Eigen::VectorXd&) { p.cohesive.tau = 1e-300; }},
      {"kappa 1e9 (the largest accepted) on half the triangles", [](InterpolationParams&, DynamicsParams&, Eigen::VectorXd& k) {
         for (Eigen::Index t = 0; t < k.size(); t += 2) k[t] = 1e9;
       }},
      {"kappa 1e-9 (the smallest accepted) everywhere", [](InterpolationParams&, DynamicsParams&, Eigen::VectorXd& k) { k.setConstant(1e-9); }},
  };
  const Scene scene = loadScene(std::string(INBETWEEN_ASSETS) + "/square-arch-stretch/scene.json");
  REQUIRE(scene.dynamics.enabled());
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  for (const Extreme& extreme : extremes) {
    INFO(extreme.name);
    InterpolationParams params = scene.interpolation;
    DynamicsParams dynamics = scene.dynamics;
    Eigen::VectorXd kappa = built.multimesh->stiffnesses();
    extreme.apply(params, dynamics, kappa);
    Multimesh mesh = *built.multimesh;
    for (int t = 0; t < mesh.triangleCount(); ++t) mesh.setStiffness(t, kappa[t]);
    SolverOptions options;
    options.maxIterations = 60;  // enough to see a frame go wrong; keeps the test short
    FrameStream stream(mesh, scene.timeline, params, options, dynamics);
    int frames = 0;
    while (!stream.done()) {
      const AnimationFrame frame = stream.next();
      INFO("frame " << frame.index);
      REQUIRE(frame.x.allFinite());
      REQUIRE(frame.plain.allFinite());
      ++frames;
    }
    CHECK(frames == scene.timeline.frameCount());
  }
  // Past the accepted range, a stiffness is refused with a message naming it (exit code 2).
  Multimesh stiff = *built.multimesh;
  stiff.setStiffness(3, 1e300);
  CHECK_THROWS_WITH(FrameStream(stiff, scene.timeline, scene.interpolation, SolverOptions{}, scene.dynamics),
                    Catch::Contains("kappa[") && Catch::Contains("[1e-9, 1e9]"));
}
