#include "animation/easing.h"
#include "animation/timeline.h"
#include "core/error.h"
#include "scene/scene_animation.h"

#include <catch2/catch.hpp>

using namespace ib;
using nlohmann::json;

namespace {

const std::vector<std::string> kKeys = {"a", "b", "c"};

// Every kind of segment: linear, each eased curve, a custom curve, a hold, a breakdown mark and a
// three-way blend.
Timeline everySegmentKind() {
  return parseTimeline(json::parse(R"({
    "fps": 24,
    "marks": [
      {"time": 0, "key": "a", "ease": "ease-in"},
      {"time": 1, "key": "b", "ease": "ease-out"},
      {"time": 1.5, "weights": {"a": 1, "c": 3}, "ease": "ease-in-out"},
      {"time": 2, "key": "c", "ease": {"cubic_bezier": [0.1, 0.9, 0.2, 1]}},
      {"time": 3, "key": "a", "ease": "hold"},
      {"time": 3.5, "key": "b", "blend": [{"c": 1}, {"a": 1, "c": 1}]},
      {"time": 4.5, "key": "a"}
    ]
  })"), kKeys, "t.json");
}

std::vector<Easing> everyEasing() {
  std::vector<Easing> all;
  for (const char* name : {"linear", "ease-in", "ease-out", "ease-in-out", "hold"}) all.push_back(namedEasing(name, ""));
  all.push_back(cubicBezierEasing({0.3, 0.8, 0.6, 0.1}, ""));
  return all;
}

std::string timelineError(const std::string& text) {
  try {
    parseTimeline(json::parse(text), kKeys, "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("easing: every curve runs from 0 to 1 within [0, 1] and never goes back") {
  for (const Easing& e : everyEasing()) {
    INFO(easingName(e.kind));
    CHECK(ease(e, 0) == 0);
    CHECK(ease(e, 1) == 1);
    double last = 0;
    for (int i = 1; i < 1000; ++i) {
      const double value = ease(e, i / 1000.0);
      CHECK(value >= 0);
      CHECK(value <= 1);
      CHECK(value >= last - 1e-12);
      last = value;
    }
  }
}

TEST_CASE("easing: eased ends start or stop with zero slope, linear ends with slope 1") {
  const double h = 1e-4;
  const auto slopeAtStart = [&](const Easing& e) { return ease(e, h) / h; };
  const auto slopeAtEnd = [&](const Easing& e) { return (1 - ease(e, 1 - h)) / h; };
  CHECK(slopeAtStart(namedEasing("ease-in", "")) < 1e-3);
  CHECK(slopeAtEnd(namedEasing("ease-out", "")) < 1e-3);
  CHECK(slopeAtStart(namedEasing("ease-in-out", "")) < 1e-3);
  CHECK(slopeAtEnd(namedEasing("ease-in-out", "")) < 1e-3);
  // The other end of a one-sided ease keeps moving.
  CHECK(slopeAtEnd(namedEasing("ease-in", "")) > 0.5);
  CHECK(slopeAtStart(namedEasing("ease-out", "")) > 0.5);
  CHECK(slopeAtStart(namedEasing("linear", "")) == Approx(1).epsilon(1e-9));
  CHECK(slopeAtEnd(namedEasing("linear", "")) == Approx(1).epsilon(1e-9));
}

TEST_CASE("timeline: w(s) is convex at every time") {
  const Timeline t = everySegmentKind();
  for (int i = -50; i <= 5000; ++i) {
    const double s = i * 1e-3;
    const Eigen::VectorXd w = t.weights(s);
    INFO("s = " << s);
    REQUIRE(w.size() == 3);
    CHECK(w.minCoeff() >= 0);
    CHECK(std::abs(w.sum() - 1) < 1e-12);
  }
}

TEST_CASE("timeline: every mark's weights are reached exactly at its time") {
  const Timeline t = everySegmentKind();
  for (const TimelineMark& m : t.marks()) {
    INFO(m.label << " at " << m.time);
    CHECK(t.weights(m.time) == m.weights);
  }
  CHECK(t.weights(1) == Eigen::Vector3d(0, 1, 0));
  CHECK(t.weights(1.5).isApprox(Eigen::Vector3d(0.25, 0, 0.75), 1e-15));
}

TEST_CASE("timeline: w(s) is continuous, except where a hold ends") {
  const Timeline t = everySegmentKind();
  // Lipschitz on a fine grid: no step may exceed a bound set by the steepest curve here (the
  // custom cubic-bezier starts with slope 9, over a 1 s segment with weights changing by 2 in L1).
  const double ds = 1e-4;
  for (int i = 0; i < 45000; ++i) {
    const double s = i * ds;
    const double step = (t.weights(s + ds) - t.weights(s)).lpNorm<1>();
    const bool holdEnds = s < 3.5 && s + ds >= 3.5;
    INFO("s = " << s);
    if (holdEnds) CHECK(step == Approx(2));  // from "a" to "b" at once
    else CHECK(step < 40 * ds);
  }
  // The hold keeps its start pose until its end.
  CHECK(t.weights(3.4999) == Eigen::Vector3d(1, 0, 0));
}

TEST_CASE("timeline: a blend segment brings in a key neither end has, and keeps to its ends") {
  const Timeline t = everySegmentKind();
  // Segment b -> a with controls {c} and {a, c}: c has weight 0 at both ends and more than a
  // quarter in the middle.
  CHECK(t.weights(3.5)(2) == 0);
  CHECK(t.weights(4.5)(2) == 0);
  CHECK(t.weights(4.0)(2) > 0.25);
}

TEST_CASE("timeline: frames fall at start + f / fps, a loop stops before the pose that repeats its start") {
  const Timeline t = everySegmentKind();
  CHECK(t.frameCount() == 4 * 24 + 12 + 1);
  CHECK(t.frameTime(24) == 1.0);
  const Timeline loop = parseTimeline(json::parse(R"({"fps": 10, "loop": true, "marks": [
    {"time": 0, "key": "a"}, {"time": 1, "key": "b"}, {"time": 2, "key": "a"}]})"), kKeys, "t.json");
  CHECK(loop.frameCount() == 20);
  CHECK(loop.weights(2.5).isApprox(loop.weights(0.5), 1e-12));
  CHECK(loop.weights(-0.5).isApprox(loop.weights(1.5), 1e-12));
}

TEST_CASE("timeline: without marks every key comes in scene order, a second apart") {
  const Timeline t = parseTimeline(json::parse(R"({"fps": 12})"), kKeys, "t.json");
  REQUIRE(t.marks().size() == 3);
  CHECK(t.fps() == 12);
  for (int k = 0; k < 3; ++k) CHECK(t.weights(k) == Eigen::Vector3d::Unit(k));
  const Timeline loop = defaultTimeline(kKeys, 24, true);
  CHECK(loop.marks().size() == 4);
  CHECK(loop.weights(3) == Eigen::Vector3d::Unit(0));
}

TEST_CASE("timeline: every malformed field is an input error naming the file, the mark and the field") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"fps": 0})", "t.json: timeline: fps: 0 is out of range (0, 1000]"},
      {R"({"speed": 1})", "timeline: unknown field \"speed\""},
      {R"({"marks": []})", "timeline: marks: must be an array of at least one mark"},
      {R"({"marks": [{"key": "a"}]})", "mark 1: missing field \"time\""},
      {R"({"marks": [{"time": 0, "key": "z"}]})", "mark 1: key: \"z\" is not a key of this scene"},
      {R"({"marks": [{"time": 0}]})", "mark 1: needs exactly one of \"key\" and \"weights\""},
      {R"({"marks": [{"time": 0, "key": "a"}, {"time": 0, "key": "b"}]})", "mark 2: time: must be later than mark 1"},
      {R"({"marks": [{"time": 0, "weights": {"a": -1}}]})", "mark 1: weights: a: -1.0 is out of range"},
      {R"({"marks": [{"time": 0, "weights": {"a": 0}}]})", "mark 1: weights: needs a positive weight"},
      {R"({"marks": [{"time": 0, "weights": {"q": 1}}]})", "mark 1: weights: \"q\" is not a key"},
      {R"({"marks": [{"time": 0, "key": "a", "ease": "bounce"}, {"time": 1, "key": "b"}]})",
       "mark 1: ease: \"bounce\" is not an easing"},
      {R"({"marks": [{"time": 0, "key": "a", "ease": "ease_in"}, {"time": 1, "key": "b"}]})",
       "[x1, y1, x2, y2]}) (did you mean \"ease-in\"?)"},
      {R"({"marks": [{"time": 0, "key": "a", "ease": {"cubic_bezier": [0, 2, 1, 1]}}, {"time": 1, "key": "b"}]})",
       "mark 1: ease: cubic_bezier: every coordinate must be in [0, 1]"},
      {R"({"marks": [{"time": 0, "key": "a", "ease": {"cubic_bezier": [0, 1]}}, {"time": 1, "key": "b"}]})",
       "mark 1: ease: cubic_bezier: must be [x1, y1, x2, y2]"},
      {R"({"marks": [{"time": 0, "key": "a", "blend": []}, {"time": 1, "key": "b"}]})", "mark 1: blend: must be an array"},
      {R"({"marks": [{"time": 0, "key": "a"}, {"time": 1, "key": "b", "ease": "linear"}]})",
       "mark 2: the last mark starts no segment"},
      {R"({"loop": true, "marks": [{"time": 0, "key": "a"}, {"time": 1, "key": "b"}]})",
       "timeline: loop: the last mark must repeat the first mark's pose"},
      {R"({"loop": "yes"})", "timeline: loop: must be true or false"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = timelineError(text);
    INFO("expected \"" << expected << "\", got \"" << message << "\"");
    CHECK(message.rfind("t.json: timeline", 0) == 0);
    CHECK(message.find(expected) != std::string::npos);
  }
}
