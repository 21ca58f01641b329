#include "timeline.h"

#include "error.h"
#include "json_fields.h"

#include <algorithm>
#include <cmath>

namespace ib {

using nlohmann::json;
using namespace json_fields;

namespace {

// de Casteljau on the control weights at parameter e: only convex combinations, so the result
// stays in the simplex (up to rounding).
Eigen::VectorXd bezierWeights(const Eigen::VectorXd& a, const std::vector<Eigen::VectorXd>& controls,
                              const Eigen::VectorXd& b, double e) {
  std::vector<Eigen::VectorXd> points{a};
  points.insert(points.end(), controls.begin(), controls.end());
  points.push_back(b);
  for (size_t level = points.size() - 1; level > 0; --level)
    for (size_t i = 0; i < level; ++i) points[i] = (1 - e) * points[i] + e * points[i + 1];
  return points.front();
}

// Relative weights {"key": value, ...}, non-negative with a positive sum, normalized to sum 1.
Eigen::VectorXd parseWeights(const json& j, const std::vector<std::string>& keys, const Context& at) {
  if (!j.is_object() || j.empty()) throw at.error("must be an object {\"key\": weight, ...} naming at least one key");
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(keys.size()));
  for (auto it = j.begin(); it != j.end(); ++it) {
    const auto found = std::find(keys.begin(), keys.end(), it.key());
    if (found == keys.end()) throw at.error(inQuotes(it.key()) + " is not a key of this scene");
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

}  // namespace

Timeline::Timeline(double fps, bool loop, std::vector<TimelineMark> marks, std::vector<TimelineSegment> segments)
    : fps_(fps), loop_(loop), marks_(std::move(marks)), segments_(std::move(segments)) {
  if (!(fps_ > 0 && std::isfinite(fps_))) throw InputError("timeline: fps must be a positive number");
  if (marks_.empty()) throw InputError("timeline: needs at least one mark");
  if (segments_.size() + 1 != marks_.size()) throw InputError("timeline: needs one segment between each two marks");
  for (size_t k = 0; k < marks_.size(); ++k) {
    if (!std::isfinite(marks_[k].time)) throw InputError("timeline: mark " + std::to_string(k + 1) + ": time must be finite");
    if (k > 0 && !(marks_[k].time > marks_[k - 1].time))
      throw InputError("timeline: mark " + std::to_string(k + 1) + ": times must increase");
  }
  if (loop_ && marks_.size() < 2) throw InputError("timeline: loop: needs at least two marks");
}

Timeline::Timeline() : Timeline(24, false, {{0, Eigen::VectorXd::Ones(1), ""}}, {}) {}

int Timeline::frameCount() const {
  const double frames = duration() * fps_;
  if (loop_) return std::max(1, static_cast<int>(std::ceil(frames - 1e-9)));
  return static_cast<int>(std::floor(frames + 1e-9)) + 1;
}

double Timeline::frameTime(int frame) const { return start() + frame / fps_; }

double Timeline::wrap(double s) const {
  if (!loop_ || (s >= start() && s < end())) return s;
  const double t = std::fmod(s - start(), duration());
  return start() + (t < 0 ? t + duration() : t);
}

Timeline::Position Timeline::locate(double time) const {
  const double s = wrap(time);
  if (s < start()) return {-1, 0};
  // The first mark after s: s lies in the segment before it.
  const auto after = std::upper_bound(marks_.begin(), marks_.end(), s,
                                      [](double value, const TimelineMark& m) { return value < m.time; });
  if (after == marks_.end()) return {static_cast<int>(segments_.size()), 0};
  const int k = static_cast<int>(after - marks_.begin()) - 1;
  return {k, (s - marks_[k].time) / (marks_[k + 1].time - marks_[k].time)};
}

Eigen::VectorXd Timeline::weights(double s) const {
  const Position p = locate(s);
  if (p.segment < 0) return marks_.front().weights;
  if (p.segment >= static_cast<int>(segments_.size())) return marks_.back().weights;
  const TimelineSegment& segment = segments_[p.segment];
  const double e = ease(segment.easing, p.u);
  const Eigen::VectorXd& a = marks_[p.segment].weights;
  const Eigen::VectorXd& b = marks_[p.segment + 1].weights;
  if (e == 0) return a;
  if (segment.controls.empty()) return (1 - e) * a + e * b;
  return bezierWeights(a, segment.controls, b, e);
}

Timeline defaultTimeline(const std::vector<std::string>& keyNames, double fps, bool loop) {
  const int m = static_cast<int>(keyNames.size());
  std::vector<TimelineMark> marks;
  const int count = std::max(m, 2) + (loop && m > 1 ? 1 : 0);
  for (int k = 0; k < count; ++k) {
    const int key = k < m ? k : (loop ? 0 : m - 1);
    marks.push_back({static_cast<double>(k), Eigen::VectorXd::Unit(m, key), keyNames[key]});
  }
  std::vector<TimelineSegment> segments(marks.size() - 1);
  for (auto& s : segments) s.easing = namedEasing("ease-in-out", "");
  return Timeline(fps, loop, std::move(marks), std::move(segments));
}

Timeline parseTimeline(const json& j, const std::vector<std::string>& keyNames, const std::string& file) {
  const Context at = Context{file, ""}.in("timeline");
  requireObject(j, at, {"fps", "loop", "marks"});
  const double fps = number(j, "fps", 24, at, 0, 1000, true);
  const bool loop = boolean(j, "loop", false, at);
  if (!j.contains("marks")) return defaultTimeline(keyNames, fps, loop);
  const json& marksJson = j["marks"];
  if (!marksJson.is_array() || marksJson.empty()) throw at.in("marks").error("must be an array of at least one mark");
  std::vector<TimelineMark> marks;
  std::vector<TimelineSegment> segments;
  for (size_t k = 0; k < marksJson.size(); ++k) {
    const json& mj = marksJson[k];
    const Context here = at.in("mark " + std::to_string(k + 1));
    requireObject(mj, here, {"time", "key", "weights", "ease", "blend"});
    if (!mj.contains("time")) throw here.error("missing field \"time\" (seconds)");
    TimelineMark mark;
    mark.time = number(mj, "time", 0, here, -1e9, 1e9);
    if (!marks.empty() && !(mark.time > marks.back().time))
      throw here.in("time").error("must be later than mark " + std::to_string(k) + "'s time");
    if (mj.contains("key") == mj.contains("weights")) throw here.error("needs exactly one of \"key\" and \"weights\"");
    if (mj.contains("key")) {
      mark.label = text(mj, "key", here);
      const auto found = std::find(keyNames.begin(), keyNames.end(), mark.label);
      if (found == keyNames.end()) throw here.in("key").error(inQuotes(mark.label) + " is not a key of this scene");
      mark.weights = Eigen::VectorXd::Unit(static_cast<Eigen::Index>(keyNames.size()), found - keyNames.begin());
    } else {
      mark.label = "breakdown";
      mark.weights = parseWeights(mj["weights"], keyNames, here.in("weights"));
    }
    const bool last = k + 1 == marksJson.size();
    if (last && (mj.contains("ease") || mj.contains("blend")))
      throw here.error("the last mark starts no segment, so it takes no \"ease\" or \"blend\"");
    if (!last) {
      TimelineSegment segment;
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

}  // namespace ib
