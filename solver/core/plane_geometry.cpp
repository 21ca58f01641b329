#include "core/plane_geometry.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace ib {

std::string formatPoint(const Eigen::Vector2d& p) {
  std::ostringstream out;
  out.precision(1);
  out << std::fixed << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

double orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

double closestParameter(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = b - a;
  const double dd = d.squaredNorm();
  return dd > 0 ? std::clamp((p - a).dot(d) / dd, 0.0, 1.0) : 0.0;
}

namespace {

bool onSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}

int sign(double v) { return (v > 0) - (v < 0); }

}  // namespace

bool segmentsMeet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                  const Eigen::Vector2d& d) {
  const int o1 = sign(orient(a, b, c)), o2 = sign(orient(a, b, d));
  const int o3 = sign(orient(c, d, a)), o4 = sign(orient(c, d, b));
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) || (o3 == 0 && onSegment(c, d, a)) ||
         (o4 == 0 && onSegment(c, d, b));
}

Eigen::Vector2d meetingPoint(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                             const Eigen::Vector2d& d) {
  const Eigen::Vector2d r = b - a, s = d - c;
  const double denominator = r.x() * s.y() - r.y() * s.x();
  if (std::abs(denominator) > 1e-12 * r.norm() * s.norm()) {
    const double t = ((c - a).x() * s.y() - (c - a).y() * s.x()) / denominator;
    return a + std::clamp(t, 0.0, 1.0) * r;
  }
  return 0.5 * (a + closestParameter(a, b, c) * r + a + closestParameter(a, b, d) * r);
}

double AffineFit::rotation() const {
  return std::abs(std::atan2(linear(1, 0) - linear(0, 1), linear(0, 0) + linear(1, 1)));
}

std::optional<AffineFit> affineFit(const Polyline& from, const Polyline& to) {
  const size_t n = std::min(from.size(), to.size());
  if (n == 0) return std::nullopt;
  Eigen::Vector2d cf = Eigen::Vector2d::Zero(), ct = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < n; ++i) cf += from[i], ct += to[i];
  cf /= static_cast<double>(n), ct /= static_cast<double>(n);
  AffineFit fit;
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero(), M = Eigen::Matrix2d::Zero();  // sums of f f^T and t f^T, 2x2
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d f = from[i] - cf, t = to[i] - ct;
    fit.fromSpread += f.squaredNorm();
    fit.toSpread += t.squaredNorm();
    S += f * f.transpose();
    M += t * f.transpose();
  }
  if (S.determinant() <= 1e-9 * fit.fromSpread * fit.fromSpread) return std::nullopt;  // a line
  fit.linear = M * S.inverse();
  fit.translation = ct - fit.linear * cf;
  // sum |A f - t|^2 = toSpread - 2 tr(A M^T) + tr(A S A^T), and A S A^T = A M^T for A = M S^-1.
  fit.residual = std::max(0.0, fit.toSpread - (fit.linear * M.transpose()).trace());
  return fit;
}

LoopPoint nearestOnLoop(const Polyline& loop, const Eigen::Vector2d& p) {
  LoopPoint best;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector2d a = loop[i], b = loop[(i + 1) % loop.size()];
    const double t = closestParameter(a, b, p);
    const Eigen::Vector2d q = a + t * (b - a);
    if ((q - p).norm() < best.distance) best = {static_cast<double>(i) + t, q, (q - p).norm()};
  }
  return best;
}

int rayCrossings(const Polyline& loop, const Eigen::Vector2d& p) {
  int crossings = 0;
  for (size_t i = 0, n = loop.size(); i < n; ++i) {
    const Eigen::Vector2d& a = loop[i];
    const Eigen::Vector2d& b = loop[(i + 1) % n];
    if ((a.y() > p.y()) == (b.y() > p.y())) continue;
    const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    if (x > p.x()) ++crossings;
  }
  return crossings;
}

ArcLengthLoop::ArcLengthLoop(Polyline points) : points_(std::move(points)) {
  cumulative_.assign(points_.size() + 1, 0.0);
  for (size_t i = 0, n = points_.size(); i < n; ++i)
    cumulative_[i + 1] = cumulative_[i] + (points_[(i + 1) % n] - points_[i]).norm();
  if (points_.empty() || !(length() > 0)) return;
  bucket_.resize(4 * points_.size());
  bucketLength_ = length() / static_cast<double>(bucket_.size());
  inverseBucketLength_ = 1 / bucketLength_;
  size_t i = 0;
  for (size_t b = 0; b < bucket_.size(); ++b) {
    const double s = static_cast<double>(b) * bucketLength_;
    while (i + 1 < points_.size() && cumulative_[i + 1] <= s) ++i;
    bucket_[b] = static_cast<int>(i);
  }
}

size_t ArcLengthLoop::segmentAt(double s) const {
  const size_t last = points_.size() - 1;
  const double b = std::floor(s * inverseBucketLength_);
  size_t i = !(b > 0) ? 0 : static_cast<size_t>(bucket_[std::min<size_t>(static_cast<size_t>(b), bucket_.size() - 1)]);
  while (i > 0 && cumulative_[i] > s) --i;  // rounding in s * inverseBucketLength_ can overshoot
  while (i < last && cumulative_[i + 1] <= s) ++i;
  return i;
}

double ArcLengthLoop::wrap(double s) const {
  const double total = length();
  if (s >= 0 && s < total) return s;
  if (s >= total && s < 2 * total) return s - total;  // exact, as fmod is (the end of a loop's last arc)
  s = std::fmod(s, total);
  return s < 0 ? s + total : s;
}

Eigen::Vector2d ArcLengthLoop::pointIn(size_t i, double local) const {
  const double span = cumulative_[i + 1] - cumulative_[i];
  const double t = span > 0 ? (local - cumulative_[i]) / span : 0.0;
  return (1 - t) * points_[i] + t * points_[(i + 1) % points_.size()];
}

double ArcLengthLoop::parameterOf(const LoopPoint& q) const {
  const size_t i = std::min(static_cast<size_t>(q.at), points_.size() - 1);
  return cumulative_[i] + (q.point - points_[i]).norm();
}

Eigen::Vector2d ArcLengthLoop::at(double s) const {
  if (points_.empty()) return Eigen::Vector2d::Zero();
  if (!(length() > 0)) return points_[0];
  const double local = wrap(s);
  return pointIn(segmentAt(local), local);
}

double ArcLengthLoop::chordDeviation(std::initializer_list<double> ends) const {
  const double total = length();
  if (points_.size() < 2 || !(total > 0) || ends.size() < 2) return 0;
  const double* s = ends.begin();
  const size_t last = points_.size() - 1;
  // The chord starts at local arc length `local` (s[k - 1] wrapped), in segment i.
  double local = wrap(s[0]);
  size_t i = segmentAt(local);
  Eigen::Vector2d a = pointIn(i, local);
  double worst = 0;  // squared: the square root of the largest square is the largest distance
  for (size_t k = 1; k < ends.size(); ++k) {
    const double end = wrap(s[k]);
    if (!(s[k] > s[k - 1])) {  // no chord: start the next one here
      local = end;
      i = segmentAt(local);
      a = pointIn(i, local);
      continue;
    }
    const bool wholeLap = s[k] - s[k - 1] >= total, wraps = wholeLap || end < local;
    // The end's segment, walking on from the start's (from point 0 past the end of the lap): the
    // points walked over are the ones between, so this costs no more than the scan below.
    size_t j = wraps ? 0 : i;
    while (j < last && cumulative_[j + 1] <= end) ++j;
    const Eigen::Vector2d b = pointIn(j, end);
    // Points strictly between the ends: after i (cumulative_[i + 1] > local) up to the end of the
    // lap if the chord wraps, then from point 0, stopping before the end.
    const auto farthest = [&](size_t from, size_t to, double below) {
      for (size_t p = from; p < to && cumulative_[p] < below; ++p)
        worst = std::max(worst, (a + closestParameter(a, b, points_[p]) * (b - a) - points_[p]).squaredNorm());
    };
    if (wholeLap) {
      farthest(0, points_.size(), total);
    } else if (wraps) {
      farthest(i + 1, points_.size(), total);
      farthest(0, j + 1, end);
    } else {
      farthest(i + 1, j + 1, end);
    }
    local = end;
    i = j;
    a = b;
  }
  return std::sqrt(worst);
}

}  // namespace ib
