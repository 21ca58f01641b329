#include "animation/frame_stream.h"
#include "core/error.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <cmath>

using namespace ib;

namespace {

// Marks (time, key) with one easing for every segment, 24 frames per second.
Timeline keyTimeline(const std::vector<std::pair<double, int>>& marks, int keyCount, const std::string& easing) {
  std::vector<TimelineMark> m;
  for (const auto& [time, key] : marks) m.push_back({time, Eigen::VectorXd::Unit(keyCount, key), "key"});
  std::vector<TimelineSegment> segments(m.size() - 1);
  for (auto& s : segments) s.easing = namedEasing(easing, "");
  return Timeline(24, false, std::move(m), std::move(segments));
}

std::vector<AnimationFrame> allFrames(FrameStream& stream) {
  std::vector<AnimationFrame> frames;
  while (!stream.done()) frames.push_back(stream.next());
  return frames;
}

// Kinetic energy of the secondary motion between frames a - 1 and a: 1/2 sum_v m_v |v - v_plain|^2,
// in shape sizes^2 / s^2.
double secondaryKineticEnergy(const std::vector<AnimationFrame>& f, int a, const Eigen::VectorXd& mass, double size,
                              double fps) {
  const Eigen::MatrixX2d relative = (f[a].x - f[a].plain) - (f[a - 1].x - f[a - 1].plain);
  return 0.5 * fps * fps * (mass.asDiagonal() * relative.rowwise().squaredNorm()).sum() / (size * size);
}

// The strip, rest -> bend -> rest over two seconds, with gravity pulling down.
DynamicsParams withGravity(double epsilon) {
  DynamicsParams d;
  d.epsilon = epsilon;
  d.gravity = {0, 10};
  return d;
}

}  // namespace

TEST_CASE("dynamics: epsilon = 0 frames are the plain interpolation frames, whatever the forces") {
  const auto f = test::strip(300, 2);
  const Timeline t = keyTimeline({{0, 0}, {1, 1}, {2, 0}}, 2, "ease-in-out");
  DynamicsParams off = withGravity(0);
  off.wind = {3, 0};
  off.mu = 4;
  FrameStream plain(f.mesh, t, {}, {}, DynamicsParams{}), forced(f.mesh, t, {}, {}, off);
  const auto a = allFrames(plain), b = allFrames(forced);
  REQUIRE(a.size() == 49);
  // A cold start is far from the minimizer, so a cold solve to the usual relative residual (1e-3)
  // can stop 2e-3 of the size away from it; the stream's warm-started frames stop much closer.
  // The reference is solved tightly.
  SolverOptions tight;
  tight.relativeTolerance = 1e-8;
  tight.maxIterations = 5000;
  Interpolator cold(f.mesh, {}, tight);
  for (size_t i = 0; i < a.size(); ++i) {
    INFO("frame " << i);
    CHECK(a[i].x == b[i].x);
    CHECK(b[i].blend == 0);
    CHECK(b[i].x == b[i].plain);
    // The same inbetween as a cold solve at the frame's weights (measured: within 1e-4 of the size).
    const Eigen::MatrixX2d x = cold.solve(t.weights(t.frameTime(static_cast<int>(i)))).x;
    CHECK((x - b[i].x).rowwise().norm().maxCoeff() < 5e-4 * f.size);
  }
}

TEST_CASE("dynamics: with gravity and epsilon > 0 inbetweens sag away from plain interpolation, keys are still hit") {
  const auto f = test::strip(300, 2);
  const Timeline t = keyTimeline({{0, 0}, {1, 1}, {2, 0}}, 2, "ease-in-out");
  FrameStream stream(f.mesh, t, {}, {}, withGravity(0.5));
  const auto frames = allFrames(stream);
  double largest = 0, sag = 0;
  for (const AnimationFrame& frame : frames) {
    largest = std::max(largest, frame.deviation);
    // Mean vertical offset from the plain frame, shape sizes (y down: sagging is positive).
    sag = std::max(sag, (frame.x - frame.plain).col(1).mean() / f.size);
  }
  INFO("largest deviation " << largest << " shape sizes, largest sag " << sag);
  CHECK(largest > 0.01);
  CHECK(sag > 0.005);
  for (int key = 0; key < 3; ++key) {
    const AnimationFrame& frame = frames[24 * key];
    const Eigen::MatrixX2d X = f.mesh.keyPositions(key == 1 ? 1 : 0);
    INFO("key frame " << 24 * key);
    CHECK(frame.blend == 0);
    CHECK((frame.x - X).rowwise().norm().maxCoeff() < 2e-3 * f.size);
  }
}

TEST_CASE("dynamics: damping lowers the kinetic energy of secondary motion over time") {
  // A fast bend that stops dead (linear easing) and is held: the strip overshoots and swings.
  const auto f = test::strip(300, 2);
  const Timeline t = keyTimeline({{0, 0}, {0.25, 1}, {3.25, 1}}, 2, "linear");
  const auto run = [&](double mu) {
    DynamicsParams d;
    d.epsilon = 1;
    d.mu = mu;
    FrameStream stream(f.mesh, t, {}, {}, d);
    return allFrames(stream);
  };
  const auto damped = run(4), free = run(0);
  const Eigen::VectorXd mass = lumpedMasses(f.mesh);
  const auto windowEnergy = [&](const std::vector<AnimationFrame>& frames, int first, int last) {
    double sum = 0;
    for (int a = first; a < last; ++a) sum += secondaryKineticEnergy(frames, a, mass, f.size, 24);
    return sum / (last - first);
  };
  // Frames 7..30 (just after the stop), then 31..54; the fade towards the last mark starts at frame 60.
  const double dampedEarly = windowEnergy(damped, 7, 31), dampedLate = windowEnergy(damped, 31, 55);
  const double freeEarly = windowEnergy(free, 7, 31), freeLate = windowEnergy(free, 31, 55);
  INFO("secondary kinetic energy, early / late: damped " << dampedEarly << " / " << dampedLate << ", undamped "
                                                         << freeEarly << " / " << freeLate);
  CHECK(dampedEarly > 1e-6);  // there is secondary motion to damp
  CHECK(dampedLate < 0.5 * dampedEarly);
  CHECK(dampedLate < 0.5 * freeLate);
  CHECK(dampedEarly < freeEarly);
}

TEST_CASE("dynamics: two runs of the same scene give bit-identical frames, and so does a restart") {
  const auto f = test::strip(300, 4);
  const Timeline t = keyTimeline({{0, 0}, {0.5, 1}, {1, 2}, {1.5, 3}}, 4, "linear");
  DynamicsParams d = withGravity(0.7);
  d.wind = {2, 0};
  d.gust = 0.5;
  FrameStream first(f.mesh, t, {}, {}, d), second(f.mesh, t, {}, {}, d);
  const auto a = allFrames(first), b = allFrames(second);
  first.restart();
  const auto c = allFrames(first);
  REQUIRE(a.size() == b.size());
  REQUIRE(a.size() == c.size());
  for (size_t i = 0; i < a.size(); ++i) {
    INFO("frame " << i);
    CHECK(a[i].x == b[i].x);
    CHECK(a[i].x == c[i].x);
  }
}

TEST_CASE("dynamics: a frame at a given time is the streamed frame, exactly with dynamics and within tolerance without") {
  const auto f = test::strip(300, 2);
  const Timeline t = keyTimeline({{0, 0}, {1, 1}}, 2, "ease-in-out");
  FrameStream dynamic(f.mesh, t, {}, {}, withGravity(0.5)), plain(f.mesh, t, {}, {}, DynamicsParams{});
  const auto streamed = allFrames(dynamic), plainFrames = allFrames(plain);
  const AnimationFrame at = dynamic.frameAt(0.51);  // frame 12 is at 0.5 s
  CHECK(at.index == 12);
  CHECK(at.x == streamed[12].x);
  const AnimationFrame cold = plain.frameAt(0.5);
  CHECK((cold.x - plainFrames[12].x).rowwise().norm().maxCoeff() < 2e-3 * f.size);
  CHECK_THROWS_AS(plain.next(), std::out_of_range);
}

TEST_CASE("dynamics: out-of-range parameters are input errors naming the field, a timeline for other keys is the caller's error") {
  const auto f = test::strip(100, 2);
  const Timeline t = keyTimeline({{0, 0}, {1, 1}}, 2, "linear");
  const auto message = [&](DynamicsParams d, const Timeline& timeline) -> std::string {
    try {
      FrameStream(f.mesh, timeline, {}, {}, d);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "no error";
  };
  DynamicsParams d;
  d.epsilon = 1.5;
  CHECK_THAT(message(d, t), Catch::Contains("dynamics: epsilon"));
  d = {};
  d.mu = -1;
  CHECK_THAT(message(d, t), Catch::Contains("dynamics: mu"));
  d = {};
  d.gravity = {NAN, 0};
  CHECK_THAT(message(d, t), Catch::Contains("dynamics: gravity"));
  CHECK_THROWS_AS(FrameStream(f.mesh, t, {}, {}, d), InputError);
  CHECK_THAT(message({}, keyTimeline({{0, 0}, {1, 2}}, 3, "linear")), Catch::Contains("timeline: has weights for 3 keys"));
  CHECK_THROWS_AS(FrameStream(f.mesh, keyTimeline({{0, 0}, {1, 2}}, 3, "linear"), {}, {}, {}), std::invalid_argument);
}

TEST_CASE("dynamics: vertex springs towards the plain inbetween leave it, springs towards a moved copy move it rigidly") {
  const auto f = test::strip(300, 2);
  SolverOptions tight;
  tight.relativeTolerance = 1e-9;
  tight.maxIterations = 2000;
  const Eigen::Vector2d w(0.4, 0.6);
  const Eigen::MatrixX2d plain = Interpolator(f.mesh, {}, tight).solve(w).x;
  Interpolator solver(f.mesh, {}, tight);
  VertexSprings springs;
  springs.stiffness = Eigen::VectorXd::Constant(f.mesh.vertexCount(), 0.3 * solver.stiffnessScale());
  springs.target = plain;
  const Eigen::MatrixX2d same = solver.solve(w, nullptr, &springs).x;
  CHECK((same - plain).rowwise().norm().maxCoeff() < 1e-5 * f.size);
  // W_I does not see translation, so springs to a translated inbetween translate the result
  // (up to the placement tie's 1e-5 pull), which rigid placement on the blend would undo.
  springs.target = plain.rowwise() + Eigen::RowVector2d(0.2 * f.size, -0.1 * f.size);
  const Eigen::MatrixX2d moved = solver.solve(w, &plain, &springs).x;
  CHECK((moved - springs.target).rowwise().norm().maxCoeff() < 1e-3 * f.size);
  // Bad springs are the caller's error.
  springs.stiffness(0) = -1;
  CHECK_THROWS_AS(solver.solve(w, nullptr, &springs), std::invalid_argument);
}
