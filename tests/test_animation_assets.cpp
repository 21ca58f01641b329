#include "animation/frame_stream.h"
#include "animation/warm_start.h"
#include "interpolation/cohesive_energy.h"
#include "interpolation/interpolator.h"
#include "meshing/multimesh_builder.h"
#include "pipeline/scene_frames.h"
#include "scene/scene.h"
#include "testkit/example_scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>

using namespace ib;

TEST_CASE("animation: every bundled asset plays its timeline with finite frames that hit its keys") {
  const std::vector<std::string> files = test::bundledSceneFiles(INBETWEEN_ASSETS);
  int withDynamics = 0;
  for (const std::string& file : files) {
    INFO("asset " << file);
    const Scene scene = loadScene(file);
    const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
    FrameStream stream = sceneFrameStream(scene, *built.multimesh);
    withDynamics += scene.dynamics.enabled();
    size_t pairs = 0;
    for (int key = 0; key < built.multimesh->keyCount(); ++key) pairs += built.multimesh->cohesivePairs(key).size();
    const double fps = scene.timeline.fps();
    while (!stream.done()) {
      const AnimationFrame frame = stream.next();
      INFO("frame " << frame.index);
      REQUIRE(frame.x.allFinite());
      REQUIRE(frame.heldPairs.size() == pairs);
      CHECK(frame.deviation < 0.5);
      // A key mark that falls on this frame: the frame is that key, where it was drawn.
      for (const TimelineMark& mark : scene.timeline.marks()) {
        const bool onFrame = std::abs((mark.time - scene.timeline.start()) * fps - frame.index) < 1e-9;
        if (!onFrame || mark.label == "breakdown") continue;
        int key = 0;
        mark.weights.maxCoeff(&key);
        const double size = stream.shapeSize();
        Eigen::Index worst = 0;
        const double off = (frame.x - built.multimesh->keyPositions(key)).rowwise().norm().maxCoeff(&worst);
        INFO("key " << key << ": vertex " << worst << " at (" << built.multimesh->keyPositions(key).row(worst) << ") is " << off
                    << " px off, iterations " << frame.iterations << (frame.converged ? "" : ", not converged"));
        CHECK(off < 5e-3 * size);
      }
    }
  }
  CHECK(files.size() >= 5);
  CHECK(withDynamics >= 1);
}

namespace {

// Largest vertex move between two frames, in the multimesh's units.
double largestMove(const Eigen::MatrixX2d& from, const Eigen::MatrixX2d& to) {
  return (to - from).rowwise().norm().maxCoeff();
}

}  // namespace

namespace {

// Sweeps from key i to key i + 1 of `scene` in 2N steps, solved as playback solves them (default
// tolerance, starts from WarmStartPredictor), and checks that on a continuous path the larger half
// of each double step carries at most 0.7 of its move (0.9 right after a release). Double steps
// where a cut lets go are counted apart: under the paper's timing where some pair changes state
// (a pair letting go is a jump by design), under release timing where some cut is within its
// release window (0 < r < 1): its sides part or shut there at the pace of the window's ramp.
// Returns the largest ratio among those.
double checkHalvedSteps(const std::string& file, const Scene& scene) {
  const int N = 16;
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  const Multimesh& mesh = *built.multimesh;
  const Eigen::MatrixX2d X0 = mesh.keyPositions(0);
  const double size = (X0.colwise().maxCoeff() - X0.colwise().minCoeff()).norm();
  Interpolator solver(mesh, scene.interpolation, SolverOptions{});
  std::vector<Eigen::MatrixX2d> keys;
  for (int k = 0; k < mesh.keyCount(); ++k) keys.push_back(mesh.keyPositions(k));
  const CohesiveEnergy cohesive(mesh, keys, scene.interpolation.cohesive);
  const auto parting = [&](const Eigen::VectorXd& w) {
    if (scene.interpolation.cohesive.timing != CutTiming::kRelease) return false;
    for (int j = 0; j < static_cast<int>(cohesive.terms().size()); ++j) {
      const double r = cohesive.ramp(j, w);
      if (r > 0 && r < 1) return true;
    }
    return false;
  };
  double largestRelease = 0;
  const int m = mesh.keyCount();
  for (int key = 0; key + 1 < m; ++key) {
    INFO("asset " << file << ", key " << key << " to " << key + 1);
    WarmStartPredictor predictor;
    std::vector<InterpolationResult> frames;
    std::vector<Eigen::VectorXd> weights;
    for (int k = 0; k <= 2 * N; ++k) {
      const double s = double(k) / (2 * N);
      weights.push_back((1 - s) * Eigen::VectorXd::Unit(m, key) + s * Eigen::VectorXd::Unit(m, key + 1));
      const std::optional<Eigen::MatrixX2d> start = predictor.predict(weights.back());
      frames.push_back(solver.solve(weights.back(), start ? &*start : nullptr));
      REQUIRE(frames.back().converged);
      predictor.remember(weights.back(), frames.back().x);
    }
    for (int k = 0; k + 2 <= 2 * N; k += 2) {
      const double whole = largestMove(frames[k].x, frames[k + 2].x);
      if (whole < 2e-4 * size) continue;  // too small a move for the ratio to mean anything
      const double half = std::max(largestMove(frames[k].x, frames[k + 1].x), largestMove(frames[k + 1].x, frames[k + 2].x));
      INFO("double step " << k / 2 << ": moves " << whole / size << " of the size, its larger half " << half / whole);
      if (frames[k].heldPairs != frames[k + 1].heldPairs || frames[k + 1].heldPairs != frames[k + 2].heldPairs ||
          parting(weights[k]) || parting(weights[k + 1]) || parting(weights[k + 2])) {
        largestRelease = std::max(largestRelease, half / whole);
        continue;
      }
      // Right after a release the shape springs open and its path bends hard: circles-open's
      // ring, let go at tau 1e-7, puts 0.79 of the next double step's move in one half. Its jump
      // is the release's; the one after that must be continuous again.
      const bool afterRelease = k >= 2 && frames[k - 1].heldPairs != frames[k].heldPairs;
      CHECK(half < (afterRelease ? 0.9 : 0.7) * whole);
    }
  }
  return largestRelease;
}

}  // namespace

TEST_CASE("interpolation: on every bundled asset, halving a step in w halves the move, except where pairs let go") {
  // On a continuous path the larger half of each double step carries about half its move (the
  // rest is curvature: at most 0.60 measured at N = 16, also when solved to 1e-7); a jump puts
  // all of it in one half (checkHalvedSteps). Under the paper's timing that includes a key's own
  // pairs when its weight reaches zero: they hold with a stiffness that vanishes with the weight,
  // so the last of them let go just before it does.
  int withNonOverlap = 0;
  for (const std::string& file : test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    const Scene scene = loadScene(file);
    // Known limitation: with non-overlap on, solves where pieces press on each other stall or
    // run to the iteration cap short of the stopping rule (circles-in-circles, key 0 to 1; the
    // frames keep the pieces apart, tests/test_examples.cpp). docs/solver.md, "Non-overlap".
    if (scene.interpolation.nonOverlap) {
      WARN(file << ": skipped, non-overlap solves at contact do not converge yet");
      ++withNonOverlap;
      continue;
    }
    checkHalvedSteps(file, scene);
  }
  CHECK(withNonOverlap <= 1);  // the one known case, not a way out for others
  // The measure sees a jump where there is one: circles-open under the paper's timing at tau
  // 1e-7, whose ring lets go at once (disc-ring's hole opened by 13% of the size in one step so).
  const std::string ring = std::string(INBETWEEN_ASSETS) + "/circles-open/scene.json";
  Scene paper = loadScene(ring);
  paper.interpolation.cohesive.timing = CutTiming::kTau;
  paper.interpolation.cohesive.tau = 1e-7;
  CHECK(checkHalvedSteps(ring, paper) > 0.9);
}
