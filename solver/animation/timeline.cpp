#include "animation/timeline.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ib {

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

}  // namespace

Timeline::Timeline(double fps, bool loop, std::vector<TimelineMark> marks, std::vector<TimelineSegment> segments)
    : fps_(fps), loop_(loop), marks_(std::move(marks)), segments_(std::move(segments)) {
  if (!(fps_ > 0 && std::isfinite(fps_))) throw std::invalid_argument("timeline: fps must be a positive number");
  if (marks_.empty()) throw std::invalid_argument("timeline: needs at least one mark");
  if (segments_.size() + 1 != marks_.size()) throw std::invalid_argument("timeline: needs one segment between each two marks");
  for (size_t k = 0; k < marks_.size(); ++k) {
    if (!std::isfinite(marks_[k].time)) throw std::invalid_argument("timeline: mark " + std::to_string(k + 1) + ": time must be finite");
    if (k > 0 && !(marks_[k].time > marks_[k - 1].time))
      throw std::invalid_argument("timeline: mark " + std::to_string(k + 1) + ": times must increase");
  }
  if (loop_ && marks_.size() < 2) throw std::invalid_argument("timeline: loop: needs at least two marks");
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

}  // namespace ib
