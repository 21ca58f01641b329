// Small exact-enough predicates on points, segments and loops in the drawing plane (pixels).
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace ib {

// An open list of points; as a loop, the last point connects back to the first.
using Polyline = std::vector<Eigen::Vector2d>;

// "(x, y)" with one decimal, for messages about places in a drawing.
std::string formatPoint(const Eigen::Vector2d& p);

// Twice the signed area of (a, b, c): positive when c lies to the left of a->b (y-up frame).
double orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

// Parameter t in [0, 1] of the point of segment [a, b] closest to p.
double closestParameter(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p);

// True when closed segments [a, b] and [c, d] share a point (crossing or touching).
bool segmentsMeet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                  const Eigen::Vector2d& d);

// A point where segments [a, b] and [c, d] meet (the midpoint of the overlap when collinear).
Eigen::Vector2d meetingPoint(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                             const Eigen::Vector2d& d);

// Where on a closed loop the point nearest to p lies: `at` = segment index + fraction along it
// (segment i runs from point i to point i + 1, the last back to point 0), the point, its distance.
struct LoopPoint {
  double at = 0;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double distance = std::numeric_limits<double>::infinity();
};
LoopPoint nearestOnLoop(const Polyline& loop, const Eigen::Vector2d& p);

// Crossings of a ray from p towards +x with the loop: odd means p is enclosed by the loop.
int rayCrossings(const Polyline& loop, const Eigen::Vector2d& p);

// The least-squares affine map x -> linear x + translation (px) taking from[i] onto to[i].
struct AffineFit {
  Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();  // 2x2
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();
  double residual = 0;    // sum over the pairs of |fit(from[i]) - to[i]|^2, px^2
  double fromSpread = 0;  // sum of |from[i] - centroid|^2, px^2
  double toSpread = 0;    // the same for `to`
  // Angle of the map's rotation (its polar part's), in [0, pi], radians.
  double rotation() const;
};

// The fit of equally long `from` and `to`; none when `from` lies on a line (or is empty).
std::optional<AffineFit> affineFit(const Polyline& from, const Polyline& to);

// Arc-length parametrization of a closed loop: s in [0, length()) walks the loop from point 0.
class ArcLengthLoop {
 public:
  ArcLengthLoop() = default;
  explicit ArcLengthLoop(Polyline points);

  double length() const { return cumulative_.back(); }
  const Polyline& points() const { return points_; }
  double parameterOfPoint(int i) const { return cumulative_[i]; }
  // The arc length at q, a point nearestOnLoop found on this loop's points().
  double parameterOf(const LoopPoint& q) const;
  // The point at arc length s, s taken modulo length().
  Eigen::Vector2d at(double s) const;
  // Largest distance from the loop between arc lengths s0 <= s1 (walking forwards, modulo
  // length()) to the chord from at(s0) to at(s1): how far the chord cuts across corners.
  double chordDeviation(double s0, double s1) const { return chordDeviation({s0, s1}); }
  // The same for a path of chords at(s0) -> at(s1) -> ... with s0 <= s1 <= ...: the largest
  // distance of the loop between consecutive ends from their chord (a chord whose ends are not
  // increasing counts 0). One lookup for the whole path; the ends after it are found by walking.
  double chordDeviation(std::initializer_list<double> ends) const;

 private:
  // The segment holding arc length s in [0, length()]: the largest i < points with
  // cumulative_[i] <= s (what a binary search over cumulative_ gives), found from its bucket.
  size_t segmentAt(double s) const;
  // Arc length s taken into [0, length()).
  double wrap(double s) const;
  // The point at arc length `local` in [0, length()] on segment i (cumulative_[i] <= local).
  Eigen::Vector2d pointIn(size_t i, double local) const;

  Polyline points_;
  std::vector<double> cumulative_;  // size points + 1; cumulative_[i] = arc length to point i
  // Lookup buckets of equal arc length (four per point: outlines crowd their points at curves): bucket_[b] is segmentAt(b * bucketLength_),
  // so a lookup starts at most a few segments before its answer instead of bisecting (Comesh
  // asks for millions of outline points).
  std::vector<int> bucket_;
  double bucketLength_ = 0, inverseBucketLength_ = 0;
};

}  // namespace ib
