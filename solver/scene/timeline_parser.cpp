// The scene file's "timeline" object (docs/scene-format.md) to a Timeline.
#include "scene/scene_animation.h"

#include "core/error.h"
#include "core/suggest.h"
#include "scene/parameter_json.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace ib {

using nlohmann::json;
using namespace json_fields;

namespace {

// Relative weights {"key": value, ...}, non-negative with a positive sum, normalized to sum 1.
Eigen::VectorXd parseWeights(const json& j, const std::vector<std::string>& keys, const Context& at) {
  if (!j.is_object() || j.empty()) throw at.error("must be an object {\"key\": weight, ...} naming at least one key");
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(keys.size()));
  for (auto it = j.begin(); it != j.end(); ++it) {
    const auto found = std::find(keys.begin(), keys.end(), it.key());
    if (found == keys.end()) throw at.error(inQuotes(it.key()) + " is not a key of this scene" + didYouMean(it.key(), keys));
    w(found - keys.begin()) = number(j, it.key(), 0, at, 0, 1e9);
  }
  if (!(w.sum() > 0)) throw at.error("needs a positive weight for at least one key");
  return w / w.sum();
}

Easing parseEasing(const json& j, const Context& at) {
  const std::string where = at.file + ": " + at.where + ": ";
  if (j.is_string()) return namedEasing(j.get<std::string>(), where);
  if (j.is_object() && j.size() == 1 && j.contains("cubic_bezier")) {
    const json& c = j["cubic_bezier"];
    if (!c.is_array() || c.size() != 4 || !std::all_of(c.begin(), c.end(), [](const json& v) { return v.is_number(); }))
      throw at.in("cubic_bezier").error("must be [x1, y1, x2, y2]");
    return cubicBezierEasing({c[0].get<double>(), c[1].get<double>(), c[2].get<double>(), c[3].get<double>()}, where);
  }
  throw at.error("must be a name (linear, ease-in, ease-out, ease-in-out, hold) or {\"cubic_bezier\": [x1, y1, x2, y2]}");
}

// A mark's "spacing", one of the words of the timeline's (the parameter table's "spacing").
SegmentSpacing parseSpacing(const json& j, SegmentSpacing fallback, const Context& at) {
  if (!j.contains("spacing")) return fallback;
  const ParameterSpec& spec = parameter("spacing");
  const json& v = j["spacing"];
  if (v.is_string())
    for (size_t i = 0; i < spec.choices.size(); ++i)
      if (spec.choices[i].word == v.get<std::string>()) return static_cast<SegmentSpacing>(i);
  std::string words;
  for (size_t i = 0; i < spec.choices.size(); ++i)
    words += (i == 0 ? "" : " or ") + inQuotes(spec.choices[i].word) + " (" + spec.choices[i].meaning + ")";
  throw at.in("spacing").error("must be " + words);
}

}  // namespace

Timeline parseTimeline(const json* timeline, const std::vector<std::string>& keyNames, const TimelineSettings& settings,
                       const std::string& file) {
  const Context at = Context{file, ""}.in("timeline");
  const double fps = settings.fps;
  const bool loop = settings.loop;
  const SegmentSpacing spacing = settings.spacing;  // every segment's unless its mark says
  std::set<std::string> allowed = parameterFields("timeline");
  allowed.insert("marks");
  if (timeline) requireObject(*timeline, at, allowed);
  if (!timeline || !timeline->contains("marks")) {
    const Timeline plain = defaultTimeline(keyNames, fps, loop);
    std::vector<TimelineSegment> segments = plain.segments();
    for (TimelineSegment& segment : segments) segment.spacingKind = spacing;
    return Timeline(fps, plain.loops(), plain.marks(), std::move(segments));
  }
  const json& marksJson = (*timeline)["marks"];
  if (!marksJson.is_array() || marksJson.empty()) throw at.in("marks").error("must be an array of at least one mark");
  std::vector<TimelineMark> marks;
  std::vector<TimelineSegment> segments;
  for (size_t k = 0; k < marksJson.size(); ++k) {
    const json& mj = marksJson[k];
    const Context here = at.in("mark " + std::to_string(k + 1));
    requireObject(mj, here, {"time", "key", "weights", "ease", "blend", "spacing"});
    if (!mj.contains("time")) throw here.error("missing field \"time\" (seconds)");
    TimelineMark mark;
    mark.time = number(mj, "time", 0, here, -1e9, 1e9);
    if (!marks.empty() && !(mark.time > marks.back().time))
      throw here.in("time").error("must be later than mark " + std::to_string(k) + "'s time");
    if (mj.contains("key") == mj.contains("weights")) throw here.error("needs exactly one of \"key\" and \"weights\"");
    if (mj.contains("key")) {
      mark.label = text(mj, "key", here);
      const auto found = std::find(keyNames.begin(), keyNames.end(), mark.label);
      if (found == keyNames.end())
        throw here.in("key").error(inQuotes(mark.label) + " is not a key of this scene" + didYouMean(mark.label, keyNames));
      mark.weights = Eigen::VectorXd::Unit(static_cast<Eigen::Index>(keyNames.size()), found - keyNames.begin());
    } else {
      mark.label = "breakdown";
      mark.weights = parseWeights(mj["weights"], keyNames, here.in("weights"));
    }
    const bool last = k + 1 == marksJson.size();
    if (last && (mj.contains("ease") || mj.contains("blend") || mj.contains("spacing")))
      throw here.error("the last mark starts no segment, so it takes no \"ease\", \"blend\" or \"spacing\"");
    if (!last) {
      TimelineSegment segment;
      segment.spacingKind = parseSpacing(mj, spacing, here);
      if (mj.contains("ease")) segment.easing = parseEasing(mj["ease"], here.in("ease"));
      if (mj.contains("blend")) {
        const json& blend = mj["blend"];
        if (!blend.is_array() || blend.empty()) throw here.in("blend").error("must be an array of control weights");
        for (size_t c = 0; c < blend.size(); ++c)
          segment.controls.push_back(parseWeights(blend[c], keyNames, here.in("blend " + std::to_string(c + 1))));
      }
      segments.push_back(std::move(segment));
    }
    marks.push_back(std::move(mark));
  }
  if (loop) {
    if (marks.size() < 2) throw at.in("loop").error("a looping timeline needs at least two marks");
    if ((marks.back().weights - marks.front().weights).cwiseAbs().maxCoeff() > 1e-9)
      throw at.in("loop").error("the last mark must repeat the first mark's pose, so the loop closes without a jump");
  }
  return Timeline(fps, loop, std::move(marks), std::move(segments));
}

Timeline parseTimeline(const json& j, const std::vector<std::string>& keyNames, const std::string& file) {
  Scene settings;
  readParameters(json{{"timeline", j}}, Context{file, ""}, settings);
  return parseTimeline(&j, keyNames, settings.timelineSettings, file);
}

}  // namespace ib
