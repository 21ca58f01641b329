// Even spacing (solver/animation/even_spacing.h, docs/animation.md "Even spacing"): the remap
// table, the timeline field, and the pacing it gives on a bundled scene.
#include "animation/even_spacing.h"
#include "animation/frame_stream.h"
#include "animation/timeline.h"
#include "core/error.h"
#include "meshing/multimesh_builder.h"
#include "scene/scene.h"
#include "scene/scene_animation.h"
#include "testkit/example_scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace ib;
using nlohmann::json;

namespace {

std::string timelineError(const std::string& text) {
  try {
    parseTimeline(json::parse(text), {"a", "b"}, "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A sampled path with these steps and no cohesive pair changing.
PathSamples smooth(const std::vector<double>& steps) { return {steps, std::vector<char>(steps.size(), 0)}; }

TimelineSegment withTable(std::vector<double> table) {
  TimelineSegment s;
  s.spacingKind = SegmentSpacing::kEven;
  s.spacing = std::move(table);
  return s;
}

// square-arch-stretch's multimesh, built once (its keys: square, arch).
const Multimesh& stretchMesh() {
  static const Multimesh mesh = [] {
    const Scene scene = loadScene(std::string(INBETWEEN_ASSETS) + "/square-arch-stretch/scene.json");
    return *buildMultimesh(scene, MultimeshBuildOptions{}).multimesh;
  }();
  return mesh;
}

// One second from the square to the arch at 24 fps: 25 frames.
Timeline squareToArch(const std::string& ease, const std::string& spacing) {
  return parseTimeline(json::parse(R"({"fps": 24, "marks": [{"time": 0, "key": "square", "ease": ")" + ease +
                                   R"(", "spacing": ")" + spacing + R"("}, {"time": 1, "key": "arch"}]})"),
                       {"square", "arch"}, "t.json");
}

InterpolationParams perKey() {
  InterpolationParams params;
  params.metric = ShapeMetric::kPerKey;  // the paper's metric: uneven pace along the stretch
  return params;
}

// Every frame of the stream, in order.
std::vector<AnimationFrame> play(const Timeline& timeline, const InterpolationParams& params) {
  FrameStream stream(stretchMesh(), timeline, params, {}, {});
  std::vector<AnimationFrame> frames;
  while (!stream.done()) frames.push_back(stream.next());
  return frames;
}

// RMS vertex move from each frame to the next, in shape sizes.
std::vector<double> frameMoves(const std::vector<AnimationFrame>& frames) {
  const double size = Interpolator(stretchMesh(), {}, {}).shapeSize();
  std::vector<double> moves;
  for (size_t f = 1; f < frames.size(); ++f)
    moves.push_back(std::sqrt((frames[f].x - frames[f - 1].x).rowwise().squaredNorm().mean()) / size);
  return moves;
}

double unevenness(const std::vector<double>& moves) {
  return *std::max_element(moves.begin(), moves.end()) / *std::min_element(moves.begin(), moves.end());
}

}  // namespace

TEST_CASE("even spacing: the remap runs from 0 to 1, through every sample, and never goes back") {
  // A path whose shape changes at speed 5 - 4 p: 5x faster at its start than at its end (each
  // step the speed at its middle times its length 1/32).
  std::vector<double> steps;
  for (int j = 0; j < 32; ++j) steps.push_back((5.0 - 4.0 * (j + 0.5) / 32) / 32);
  const std::vector<double> table = spacingTable(smooth(steps));
  REQUIRE(table.size() == 33);
  CHECK(table.front() == 0);
  CHECK(table.back() == 1);
  const TimelineSegment segment = withTable(table);
  CHECK(pathParameter(segment, 0) == 0);
  CHECK(pathParameter(segment, 1) == 1);
  for (size_t j = 0; j < table.size(); ++j) CHECK(pathParameter(segment, table[j]) == Approx(j / 32.0).margin(1e-12));
  double last = 0;
  for (int i = 1; i <= 2000; ++i) {
    const double p = pathParameter(segment, i / 2000.0);
    CHECK(p >= last);
    last = p;
  }
  // The fast start is walked slowly: a tenth of the change L(p) = (5 p - 2 p^2) / 3 is done at
  // p = 0.0607, not 0.1.
  CHECK(pathParameter(segment, 0.1) == Approx((5 - std::sqrt(25 - 8 * 0.3)) / 4).margin(1e-4));
  // Equal steps: the identity, within rounding.
  const TimelineSegment even = withTable(spacingTable(smooth(std::vector<double>(8, 0.25))));
  for (int i = 0; i <= 100; ++i) CHECK(pathParameter(even, i / 100.0) == Approx(i / 100.0).margin(1e-12));
  // No table: the identity, exactly.
  CHECK(pathParameter(TimelineSegment{}, 0.37) == 0.37);
}

TEST_CASE("even spacing: a still path keeps no table, a release counts as the pace around it, a jump twice its neighbour") {
  CHECK(spacingTable(smooth(std::vector<double>(10, 0.0))).empty());
  // A cut unzipping over samples 4..6 (pairs let go there): those steps count as the steps around.
  PathSamples unzip = smooth({1, 1, 1, 2, 40, 30, 50, 4, 4, 4});
  unzip.pairsChange[4] = unzip.pairsChange[5] = unzip.pairsChange[6] = 1;
  const std::vector<double> table = spacingTable(unzip);
  const double unit = table[1];  // one step of 1
  CHECK(table[5] - table[4] == Approx(2.5 * unit));  // 2 and 4 interpolated, a quarter of the way
  CHECK(table[6] - table[5] == Approx(3 * unit));
  CHECK(table[7] - table[6] == Approx(3.5 * unit));
  // A jump without a release (a solve into another minimum): twice its longer neighbour.
  std::vector<double> steps(10, 1.0);
  steps[4] = 50;
  const std::vector<double> capped = spacingTable(smooth(steps));
  CHECK(capped[5] - capped[4] == Approx(2 * (capped[4] - capped[3])));
  // Zero steps are raised a little, so the table still increases strictly.
  std::vector<double> flat(10, 1.0);
  flat[2] = 0;
  const std::vector<double> raised = spacingTable(smooth(flat));
  CHECK(raised[3] > raised[2]);
  CHECK_THROWS_AS(spacingTable(smooth(steps), EvenSpacingOptions{33, 1.0}), InputError);
}

TEST_CASE("even spacing: the timeline takes only tables from 0 to 1 that increase") {
  const std::vector<TimelineMark> marks{{0, Eigen::Vector2d(1, 0), "a"}, {1, Eigen::Vector2d(0, 1), "b"}};
  CHECK_NOTHROW(Timeline(24, false, marks, {withTable({0, 0.7, 1})}));
  CHECK_NOTHROW(Timeline(24, false, marks, {withTable({})}));
  CHECK_THROWS_AS(Timeline(24, false, marks, {withTable({0, 1.2, 1})}), std::invalid_argument);
  CHECK_THROWS_AS(Timeline(24, false, marks, {withTable({0.1, 1})}), std::invalid_argument);
  CHECK_THROWS_AS(Timeline(24, false, marks, {withTable({0})}), std::invalid_argument);
}

TEST_CASE("even spacing: the timeline's spacing field, per mark and for the whole timeline") {
  const auto kinds = [](const std::string& text) {
    const Timeline timeline = parseTimeline(json::parse(text), {"a", "b"}, "t.json");
    std::vector<SegmentSpacing> out;
    for (const TimelineSegment& s : timeline.segments()) out.push_back(s.spacingKind);
    return out;
  };
  using S = SegmentSpacing;
  CHECK(kinds(R"({"marks": [{"time": 0, "key": "a"}, {"time": 1, "key": "b"}, {"time": 2, "key": "a"}]})") ==
        std::vector<S>{S::kWeights, S::kWeights});
  CHECK(kinds(R"({"marks": [{"time": 0, "key": "a", "spacing": "even"}, {"time": 1, "key": "b"}, {"time": 2, "key": "a"}]})") ==
        std::vector<S>{S::kEven, S::kWeights});
  CHECK(kinds(R"({"spacing": "even", "marks": [{"time": 0, "key": "a", "spacing": "weights"}, {"time": 1, "key": "b"},
                  {"time": 2, "key": "a"}]})") == std::vector<S>{S::kWeights, S::kEven});
  CHECK(kinds(R"({"spacing": "even"})") == std::vector<S>{S::kEven});  // the default timeline too
  CHECK(timelineError(R"({"marks": [{"time": 0, "key": "a", "spacing": "uniform"}, {"time": 1, "key": "b"}]})") ==
        "t.json: timeline: mark 1: spacing: must be \"weights\" (equal steps of the weights) or \"even\" (equal steps of the shape)");
  CHECK(timelineError(R"({"spacing": 1})").find("t.json: timeline: spacing: must be") == 0);
  CHECK(timelineError(R"({"marks": [{"time": 0, "key": "a"}, {"time": 1, "key": "b", "spacing": "even"}]})") ==
        "t.json: timeline: mark 2: the last mark starts no segment, so it takes no \"ease\", \"blend\" or \"spacing\"");
}

TEST_CASE("even spacing: on square-arch-stretch with the per-key metric the shape changes evenly, and the keys still land") {
  const InterpolationParams params = perKey();
  const std::vector<double> before = frameMoves(play(squareToArch("linear", "weights"), params));
  const std::vector<AnimationFrame> frames = play(squareToArch("linear", "even"), params);
  const std::vector<double> after = frameMoves(frames);
  REQUIRE(frames.size() == 25);
  INFO("max/min per-frame RMS move, weights " << unevenness(before) << ", even " << unevenness(after));
  CHECK(unevenness(before) > 2);    // measured 4.00 (the snap into the stretched arch)
  CHECK(unevenness(after) < 1.15);  // measured 1.04
  // The marks are the keys, exactly, and the frames there are the drawn keys.
  CHECK(frames.front().weights == Eigen::Vector2d(1, 0));
  CHECK(frames.back().weights == Eigen::Vector2d(0, 1));
  const double size = Interpolator(stretchMesh(), {}, {}).shapeSize();
  CHECK((frames.back().x - stretchMesh().keyPositions(1)).rowwise().norm().maxCoeff() < 5e-3 * size);
}

TEST_CASE("even spacing: easing still applies, around the evenly paced path") {
  const InterpolationParams params = perKey();
  FrameStream stream(stretchMesh(), squareToArch("ease-in-out", "even"), params, {}, {});
  const Timeline& played = stream.timeline();
  const TimelineSegment& segment = played.segments()[0];
  REQUIRE(segment.spacing.size() == static_cast<size_t>(EvenSpacingOptions{}.samples));
  // w(s) is the path at p(ease(u)).
  for (int i = 0; i <= 10; ++i) {
    const double u = i / 10.0;
    CHECK((played.weights(u) - played.pathWeights(0, pathParameter(segment, ease(segment.easing, u)))).norm() < 1e-15);
  }
  std::vector<AnimationFrame> frames;
  while (!stream.done()) frames.push_back(stream.next());
  const std::vector<double> moves = frameMoves(frames);
  const double middle = moves[moves.size() / 2];
  // Slow at both ends (ease-in-out's zero slopes), about as slow at either.
  CHECK(moves.front() < 0.3 * middle);
  CHECK(moves.back() < 0.3 * middle);
  CHECK(moves.front() / moves.back() == Approx(1).margin(0.25));
}

TEST_CASE("even spacing: the tables and frames are the same bit for bit on every run") {
  const InterpolationParams params = perKey();
  FrameStream a(stretchMesh(), squareToArch("linear", "even"), params, {}, {});
  FrameStream b(stretchMesh(), squareToArch("linear", "even"), params, {}, {});
  CHECK(a.timeline().segments()[0].spacing == b.timeline().segments()[0].spacing);
  const AnimationFrame first = a.next();
  a.next();
  a.restart();
  CHECK(a.next().x == first.x);
  CHECK(b.next().x == first.x);
  // A timeline that already carries its tables is played as it is.
  FrameStream c(stretchMesh(), a.timeline(), params, {}, {});
  CHECK(c.timeline().segments()[0].spacing == a.timeline().segments()[0].spacing);
  CHECK(!needsEvenSpacing(a.timeline()));
}

TEST_CASE("even spacing: every bundled asset plays evenly spaced with finite frames that hit its keys") {
  for (const std::string& file : test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    INFO("asset " << file);
    const Scene scene = loadScene(file);
    const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
    std::vector<TimelineSegment> segments = scene.timeline.segments();
    for (TimelineSegment& segment : segments) segment.spacingKind = SegmentSpacing::kEven;
    const Timeline& t = scene.timeline;
    FrameStream stream(*built.multimesh, Timeline(t.fps(), t.loops(), t.marks(), segments), scene.interpolation, {},
                       scene.dynamics);
    const double size = stream.shapeSize();
    // Every mark's weights at its time, exactly.
    for (const TimelineMark& mark : t.marks()) {
      const bool wraps = t.loops() && mark.time == t.end();  // a loop's end is its start again
      CHECK(stream.timeline().weights(mark.time) == (wraps ? t.marks().front().weights : mark.weights));
    }
    while (!stream.done()) {
      const AnimationFrame frame = stream.next();
      INFO("frame " << frame.index);
      REQUIRE(frame.x.allFinite());
      for (const TimelineMark& mark : t.marks()) {
        if (std::abs((mark.time - t.start()) * t.fps() - frame.index) > 1e-9) continue;
        if (mark.label == "breakdown") continue;
        int key = 0;
        mark.weights.maxCoeff(&key);
        CHECK((frame.x - built.multimesh->keyPositions(key)).rowwise().norm().maxCoeff() < 5e-3 * size);
      }
    }
  }
}
