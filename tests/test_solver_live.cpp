// The solver's live API: parameters and stiffness changed between solves, cancellation from
// another thread, and the frame stream's parameter changes, cancelled frames and checkpoints.
#include "animation/frame_stream.h"
#include "core/error.h"
#include "interpolation/interpolator.h"
#include "meshing/multimesh_builder.h"
#include "scene/scene.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <random>
#include <stdexcept>
#include <pthread.h>
#include <thread>
#include <time.h>

using namespace ib;

namespace {

double largestDistance(const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b) {
  return (a - b).rowwise().norm().maxCoeff();
}

// Every parameter away from its default: stiffer, earlier-separating, shear-easy pairs, W_O on.
InterpolationParams changedParams() {
  InterpolationParams p;
  p.cohesive.timing = CutTiming::kTau;  // from the default release timing to the paper's
  p.cohesive.lambda = 900;
  p.cohesive.tau = 3e-4;
  p.cohesive.alpha = 0.8;
  p.nonOverlap = true;
  return p;
}

// kappa in [0.5, 4] per triangle, from a fixed seed.
Eigen::VectorXd randomStiffness(int triangles) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> kappa(0.5, 4.0);
  Eigen::VectorXd out(triangles);
  for (int t = 0; t < triangles; ++t) out(t) = kappa(random);
  return out;
}

Multimesh withStiffness(Multimesh mesh, const Eigen::VectorXd& kappa) {
  for (int t = 0; t < mesh.triangleCount(); ++t) mesh.setStiffness(t, kappa(t));
  return mesh;
}

// The bundled scene with dynamics (epsilon 0.6, gravity, a stiff painted top), built without
// Comesh Optimization.
struct DynamicScene {
  Scene scene;
  std::shared_ptr<const Multimesh> mesh;
};
DynamicScene squareArchStretch() {
  DynamicScene out{loadScene(std::string(INBETWEEN_ASSETS) + "/square-arch-stretch/scene.json"), nullptr};
  out.mesh = std::make_shared<const Multimesh>(*buildMultimesh(out.scene, MultimeshBuildOptions{}).multimesh);
  return out;
}

}  // namespace

TEST_CASE("live solver: after setParameters a solve gives a fresh Interpolator's inbetween, in the same factor pattern") {
  const auto f = test::gluedSquares(9, 1.0, 0.3);
  const Eigen::Vector2d w(0.4, 0.6);
  Interpolator live(f.mesh, {}, ib::test::tightSolverOptions());
  live.solve(w);  // history and a factor of the old parameters, to be forgotten
  const long nonZeros = live.factorNonZeros();
  live.setParameters(changedParams());
  const InterpolationResult changed = live.solve(w);
  const InterpolationResult fresh = Interpolator(f.mesh, changedParams(), ib::test::tightSolverOptions()).solve(w);
  REQUIRE(changed.converged);
  CHECK(largestDistance(changed.x, fresh.x) < 1e-6 * f.size);
  CHECK(largestDistance(changed.x, fresh.x) == 0);  // bit for bit, as interpolator.h says
  CHECK(live.factorNonZeros() == nonZeros);
  // And back: W_O off again, the defaults' inbetween.
  live.setParameters({});
  const InterpolationResult back = live.solve(w);
  CHECK(largestDistance(back.x, Interpolator(f.mesh, {}, ib::test::tightSolverOptions()).solve(w).x) < 1e-6 * f.size);
  CHECK(live.factorNonZeros() == nonZeros);
}

TEST_CASE("live solver: after setStiffness a solve gives the inbetween of a fresh Interpolator with that stiffness") {
  for (const auto& f : {test::strip(6000, 2), test::gluedSquares(9, 1.0, 0.3)}) {
    INFO(f.name);
    const Eigen::Vector2d w(0.5, 0.5);
    const Eigen::VectorXd kappa = randomStiffness(f.mesh.triangleCount());
    Interpolator live(f.mesh, {}, ib::test::tightSolverOptions());
    const double scale = live.stiffnessScale();
    live.solve(w);
    const long nonZeros = live.factorNonZeros();
    live.setStiffness(kappa);
    const InterpolationResult changed = live.solve(w);
    Interpolator fresh(withStiffness(f.mesh, kappa), {}, ib::test::tightSolverOptions());
    REQUIRE(changed.converged);
    const InterpolationResult expected = fresh.solve(w);
    CHECK(largestDistance(changed.x, expected.x) < 1e-6 * f.size);
    CHECK(largestDistance(changed.x, expected.x) == 0);  // bit for bit
    CHECK(live.factorNonZeros() == nonZeros);
    CHECK(live.stiffnessScale() == fresh.stiffnessScale());
    CHECK(live.stiffnessScale() != scale);
  }
}

TEST_CASE("live solver: bad live values name what is wrong and change nothing") {
  const auto f = test::gluedSquares(7, 1.0, 0.3);
  const Eigen::Vector2d w(0.3, 0.7);
  Interpolator live(f.mesh, {}, ib::test::tightSolverOptions());
  InterpolationParams bad;
  bad.cohesive.alpha = 1.5;
  REQUIRE_THROWS_WITH(live.setParameters(bad), Catch::Contains("alpha"));
  bad = {};
  bad.cohesive.tau = 0;
  REQUIRE_THROWS_AS(live.setParameters(bad), InputError);
  Eigen::VectorXd kappa = Eigen::VectorXd::Ones(f.mesh.triangleCount());
  REQUIRE_THROWS_AS(live.setStiffness(kappa.head(3)), std::invalid_argument);
  kappa(5) = -1;
  REQUIRE_THROWS_WITH(live.setStiffness(kappa), Catch::Contains("kappa[5]"));
  kappa(5) = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_AS(live.setStiffness(kappa), InputError);
  CHECK(largestDistance(live.solve(w).x, Interpolator(f.mesh, {}, ib::test::tightSolverOptions()).solve(w).x) < 1e-6 * f.size);
}

TEST_CASE("live solver: a cancel flag set from another thread stops a solve that would run for minutes, at a finite iterate") {
  // Plain local-global to 1e-12 on a 10k-vertex bend needs thousands of iterations, and the
  // iteration cap is out of reach: the solve ends only when the flag stops it.
  const auto f = test::strip(10000, 2);
  SolverOptions slow;
  slow.andersonDepth = 0;
  slow.relativeTolerance = 1e-12;
  slow.keyTolerance = 1e-12;
  slow.maxIterations = 100000;
  Interpolator solver(f.mesh, {}, slow);
  std::atomic<bool> cancel{true};
  solver.setCancelFlag(&cancel);
  // Raised before the solve: no iteration, the (placed) start comes back. This solve also
  // factorizes H, so that the next one is iterating soon after it starts.
  const InterpolationResult none = solver.solve(Eigen::Vector2d(0.5, 0.5));
  CHECK(none.cancelled);
  CHECK(none.iterations == 0);
  CHECK(none.x.allFinite());
  cancel = false;
  // The other thread raises the flag once the solving thread has spent 50 ms of CPU time in the
  // solve: past its start (a millisecond or two; H is factorized already), into its iterations,
  // however busy the machine is.
  clockid_t solving{};
  REQUIRE(pthread_getcpuclockid(pthread_self(), &solving) == 0);
  const auto cpuSeconds = [&] {
    timespec t{};
    clock_gettime(solving, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  };
  std::atomic<bool> started{false}, returned{false};
  std::atomic<double> from{0};
  std::thread canceller([&] {
    while (!started) std::this_thread::yield();
    while (!returned && cpuSeconds() < from + 0.05) std::this_thread::yield();
    cancel = true;
  });
  from = cpuSeconds();
  started = true;
  const InterpolationResult r = solver.solve(Eigen::Vector2d(0.5, 0.5));
  returned = true;  // a solve that ended on its own fails the checks below instead of hanging here
  canceller.join();
  CHECK(r.cancelled);
  CHECK_FALSE(r.converged);
  CHECK(r.iterations > 0);
  CHECK(r.iterations < slow.maxIterations);
  CHECK(r.x.allFinite());
  CHECK(r.energy <= r.startEnergy);
  // Cleared: solves run to the end again.
  cancel = false;
  solver.setCancelFlag(nullptr);
  SolverOptions normal;
  Interpolator quick(f.mesh, {}, normal);
  quick.setCancelFlag(&cancel);
  const InterpolationResult done = quick.solve(Eigen::Vector2d(0.5, 0.5));
  CHECK_FALSE(done.cancelled);
  CHECK(done.converged);
}

TEST_CASE("frame stream: parameters and stiffness changed before the first frame play a fresh stream's frames") {
  const DynamicScene d = squareArchStretch();
  const Multimesh& mesh = *d.mesh;
  const Eigen::VectorXd kappa = 2.0 * mesh.stiffnesses();
  DynamicsParams dynamics = d.scene.dynamics;
  dynamics.epsilon = 0.9;
  dynamics.gravity = Eigen::Vector2d(1, 2);
  FrameStream live(mesh, d.scene.timeline, d.scene.interpolation, {}, d.scene.dynamics);
  live.setParameters(changedParams(), dynamics);
  live.setStiffness(kappa);
  FrameStream fresh(withStiffness(mesh, kappa), d.scene.timeline, changedParams(), {}, dynamics);
  const double size = live.shapeSize();
  for (int k = 0; k < 16; ++k) {
    const AnimationFrame a = live.next(), b = fresh.next();
    INFO("frame " << k);
    REQUIRE(largestDistance(a.x, b.x) < 1e-9 * size);
  }
  REQUIRE_THROWS_WITH(live.setParameters({}, DynamicsParams{-1}), Catch::Contains("epsilon"));
  REQUIRE_THROWS_AS(live.setStiffness(kappa.head(2)), std::invalid_argument);
}

TEST_CASE("frame stream: a parameter change takes effect from the next frame, and dynamics can be switched on") {
  const auto f = test::gluedSquares(9, 1.0, 0.3);
  const Timeline timeline = defaultTimeline({"glued", "apart"});
  // Every parameter changed but the cut timing: under tau a cut's state depends on the frames
  // before (the seam, parting under release timing, stays apart), so only under release timing
  // is the next frame the fresh stream's.
  InterpolationParams changed = changedParams();
  changed.cohesive.timing = CutTiming::kRelease;
  FrameStream live(f.mesh, timeline, {}, ib::test::tightSolverOptions(), {});
  FrameStream reference(f.mesh, timeline, changed, ib::test::tightSolverOptions(), {});
  for (int k = 0; k < 5; ++k) reference.next(), live.next();
  live.setParameters(changed, {});
  REQUIRE(live.nextFrame() == 5);
  CHECK(largestDistance(live.next().x, reference.next().x) < 1e-6 * f.size);
  // Dynamics switched on mid-stream: the frames move away from the plain inbetweens.
  DynamicsParams dynamics;
  dynamics.epsilon = 1;
  dynamics.gravity = Eigen::Vector2d(0, 40);
  live.setParameters(changed, dynamics);
  double deviation = 0;
  for (int k = 0; k < 6; ++k) deviation = std::max(deviation, live.next().deviation);
  CHECK(deviation > 1e-3);
}

TEST_CASE("frame stream: a cancelled frame comes back marked and the stream solves that frame again") {
  const DynamicScene d = squareArchStretch();
  FrameStream stream(*d.mesh, d.scene.timeline, d.scene.interpolation, {}, d.scene.dynamics);
  FrameStream reference(*d.mesh, d.scene.timeline, d.scene.interpolation, {}, d.scene.dynamics);
  std::atomic<bool> cancel{false};
  stream.setCancelFlag(&cancel);
  for (int k = 0; k < 6; ++k) stream.next(), reference.next();
  cancel = true;
  const AnimationFrame cancelled = stream.next();
  CHECK(cancelled.cancelled);
  CHECK(cancelled.index == 6);
  CHECK(cancelled.x.allFinite());
  CHECK(stream.nextFrame() == 6);
  cancel = false;
  const double size = stream.shapeSize();
  for (int k = 6; k < 12; ++k) {
    const AnimationFrame a = stream.next(), b = reference.next();
    INFO("frame " << k);
    REQUIRE(a.index == k);
    CHECK_FALSE(a.cancelled);
    CHECK(largestDistance(a.x, b.x) < 1e-3 * size);
  }
}

TEST_CASE("frame stream: with dynamics, the 10 frames after resuming at frame 12 are the uninterrupted stream's within 1e-3 shape sizes") {
  // Solved to 1e-4: a resume starts without the solver's history, so its frames differ from the
  // uninterrupted ones as much as either differs from the exact frames, in proportion to the
  // tolerance (measured: 1.2e-4 shape sizes at 1e-4; 1.4e-3 at the default 1e-3, where the
  // uninterrupted stream is itself 7e-4 from the frames solved to 1e-10).
  const DynamicScene d = squareArchStretch();
  REQUIRE(d.scene.dynamics.enabled());
  const InterpolationParams params = d.scene.interpolation;
  SolverOptions options;
  options.relativeTolerance = 1e-4;
  FrameStream stream(*d.mesh, d.scene.timeline, params, options, d.scene.dynamics);
  std::vector<AnimationFrame> uninterrupted;
  FrameStream::Checkpoint at12;
  CHECK(at12.frame() == -1);
  REQUIRE_THROWS_AS(stream.resume(at12), std::invalid_argument);
  while (stream.nextFrame() < 22) {
    if (stream.nextFrame() == 12) at12 = stream.checkpoint();
    uninterrupted.push_back(stream.next());
  }
  REQUIRE(at12.frame() == 12);
  const double size = stream.shapeSize();
  double largest = 0, largestDeviation = 0;
  std::vector<AnimationFrame> resumed;
  stream.resume(at12);
  REQUIRE(stream.nextFrame() == 12);
  for (int k = 12; k < 22; ++k) {
    resumed.push_back(stream.next());
    largest = std::max(largest, largestDistance(resumed.back().x, uninterrupted[k].x));
    largestDeviation = std::max(largestDeviation, uninterrupted[k].deviation);
  }
  INFO("largest distance " << largest / size << " shape sizes; dynamics deviate by up to " << largestDeviation);
  CHECK(largestDeviation > 1e-3);  // dynamics really carry the motion
  CHECK(largest < 1e-3 * size);
  // A resume forgets the solver's history, so the same checkpoint repeats its frames exactly.
  stream.resume(at12);
  for (int k = 12; k < 22; ++k) REQUIRE(largestDistance(stream.next().x, resumed[k - 12].x) == 0);
  // Another stream of the same multimesh and timeline takes the checkpoint too.
  FrameStream other(*d.mesh, d.scene.timeline, params, options, d.scene.dynamics);
  other.resume(at12);
  CHECK(largestDistance(other.next().x, resumed[0].x) == 0);
  REQUIRE_THROWS_AS(stream.seek(3), std::logic_error);
}

TEST_CASE("frame stream: without dynamics, seek gives the uninterrupted stream's frame within the tolerance") {
  const auto f = test::strip(300, 2);
  const Timeline timeline = defaultTimeline({"rest", "bend"});
  FrameStream stream(f.mesh, timeline, {}, {}, {});
  std::vector<AnimationFrame> frames;
  while (!stream.done()) frames.push_back(stream.next());
  stream.seek(10, &frames[9]);
  REQUIRE(stream.nextFrame() == 10);
  CHECK(largestDistance(stream.next().x, frames[10].x) < 1e-3 * f.size);
  stream.seek(3);
  CHECK(largestDistance(stream.next().x, frames[3].x) < 1e-3 * f.size);
  REQUIRE_THROWS_AS(stream.seek(static_cast<int>(frames.size()) + 1), std::out_of_range);
}
