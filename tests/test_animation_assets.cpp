#include "example_scenes.h"
#include "frame_stream.h"
#include "multimesh_builder.h"
#include "scene.h"

#include <catch2/catch.hpp>

using namespace ib;

TEST_CASE("animation: every bundled asset plays its timeline with finite frames that hit its keys") {
  const std::vector<std::string> files = test::bundledSceneFiles(INBETWEEN_ASSETS);
  int withDynamics = 0;
  for (const std::string& file : files) {
    INFO("asset " << file);
    const Scene scene = loadScene(file);
    const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
    FrameStream stream(*built.multimesh, scene.timeline, interpolationParams(scene.solver), {}, scene.dynamics);
    withDynamics += scene.dynamics.enabled();
    const double fps = scene.timeline.fps();
    while (!stream.done()) {
      const AnimationFrame frame = stream.next();
      INFO("frame " << frame.index);
      REQUIRE(frame.x.allFinite());
      CHECK(frame.deviation < 0.5);
      // A key mark that falls on this frame: the frame is that key, where it was drawn.
      for (const TimelineMark& mark : scene.timeline.marks()) {
        const bool onFrame = std::abs((mark.time - scene.timeline.start()) * fps - frame.index) < 1e-9;
        if (!onFrame || mark.label == "breakdown") continue;
        int key = 0;
        mark.weights.maxCoeff(&key);
        const double size = stream.shapeSize();
        CHECK((frame.x - built.multimesh->keyPositions(key)).rowwise().norm().maxCoeff() < 5e-3 * size);
      }
    }
  }
  CHECK(files.size() >= 5);
  CHECK(withDynamics >= 1);
}
