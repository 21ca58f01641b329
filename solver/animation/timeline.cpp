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

// Fritsch-Carlson slope of the inverse y(x) at node j, x the table, y_j = j / (K - 1): the
// weighted harmonic mean of the neighbouring secants inside (which keeps the cubic monotone); at
// either end the three-point estimate, kept between 0 and 3 times the end secant (as MATLAB's
// pchip), which follows a pace that changes fast towards a key better than the end secant alone.
double inverseSlope(const std::vector<double>& x, size_t j) {
  const double dy = 1.0 / static_cast<double>(x.size() - 1);
  const size_t n = x.size();
  if (n == 2) return dy / (x[1] - x[0]);
  if (j == 0 || j + 1 == n) {
    // h0, d0: the end interval and its secant; h1, d1: the next one in.
    const double h0 = j == 0 ? x[1] - x[0] : x[n - 1] - x[n - 2], h1 = j == 0 ? x[2] - x[1] : x[n - 2] - x[n - 3];
    const double d0 = dy / h0, d1 = dy / h1;
    return std::clamp(((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1), 0.0, 3 * d0);
  }
  const double h0 = x[j] - x[j - 1], h1 = x[j + 1] - x[j];
  const double w0 = 2 * h1 + h0, w1 = h1 + 2 * h0;
  return (w0 + w1) / (w0 * h0 / dy + w1 * h1 / dy);
}

void checkSpacing(const std::vector<double>& table, size_t segment) {
  if (table.empty()) return;
  const std::string at = "timeline: segment " + std::to_string(segment + 1) + ": spacing: ";
  if (table.size() < 2) throw std::invalid_argument(at + "needs at least two samples");
  if (table.front() != 0 || table.back() != 1) throw std::invalid_argument(at + "must run from 0 to 1");
  for (size_t j = 1; j < table.size(); ++j)
    if (!(table[j] > table[j - 1])) throw std::invalid_argument(at + "must increase strictly");
}

}  // namespace

double pathParameter(const TimelineSegment& segment, double e) {
  const std::vector<double>& x = segment.spacing;
  if (!(e > 0)) return 0;
  if (e >= 1) return 1;
  if (x.empty()) return e;
  // The interval [x_j, x_j+1] holding e, then the cubic Hermite piece of the inverse on it.
  const size_t j = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), e) - x.begin()) - 1;
  const double h = x[j + 1] - x[j], t = (e - x[j]) / h;
  const double dy = 1.0 / static_cast<double>(x.size() - 1);
  const double y0 = static_cast<double>(j) * dy, y1 = static_cast<double>(j + 1) * dy;
  const double t2 = t * t, t3 = t2 * t;
  const double y = (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * h * inverseSlope(x, j) + (-2 * t3 + 3 * t2) * y1 +
                   (t3 - t2) * h * inverseSlope(x, j + 1);
  return std::clamp(y, y0, y1);  // rounding never leaves the interval, so p stays monotone
}

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
  for (size_t k = 0; k < segments_.size(); ++k) checkSpacing(segments_[k].spacing, k);
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
  return pathWeights(p.segment, pathParameter(segment, ease(segment.easing, p.u)));
}

Eigen::VectorXd Timeline::pathWeights(int segment, double p) const {
  if (segment < 0 || segment >= static_cast<int>(segments_.size()))
    throw std::out_of_range("timeline: no segment " + std::to_string(segment));
  const Eigen::VectorXd& a = marks_[segment].weights;
  const Eigen::VectorXd& b = marks_[segment + 1].weights;
  const std::vector<Eigen::VectorXd>& controls = segments_[segment].controls;
  p = std::clamp(p, 0.0, 1.0);
  if (p == 0) return a;
  if (controls.empty()) return (1 - p) * a + p * b;
  return bezierWeights(a, controls, b, p);
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
