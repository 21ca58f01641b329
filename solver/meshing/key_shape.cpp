#include "meshing/key_shape.h"

#include "core/error.h"
#include "core/plane_geometry.h"
#include "meshing/outline_corners.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

namespace ib {

namespace {

struct Snap {
  int loop = -1, point = -1;
  double distance = std::numeric_limits<double>::infinity();
};

// Moves p onto the nearest outline point, inserting a loop point there unless one is within
// 1e-6 px. Returns where it landed and how far p was.
Snap snapOntoLoops(std::vector<ShapeLoop>& loops, const Eigen::Vector2d& p) {
  Snap best;
  int bestSegment = -1;
  double bestT = 0;
  for (size_t l = 0; l < loops.size(); ++l) {
    const Polyline& pts = loops[l].points;
    for (size_t i = 0, n = pts.size(); i < n; ++i) {
      const Eigen::Vector2d& a = pts[i];
      const Eigen::Vector2d& b = pts[(i + 1) % n];
      const double t = closestParameter(a, b, p);
      const double d = (a + t * (b - a) - p).norm();
      if (d < best.distance) {
        best.distance = d;
        best.loop = static_cast<int>(l);
        bestSegment = static_cast<int>(i);
        bestT = t;
      }
    }
  }
  if (best.loop < 0) return best;
  ShapeLoop& loop = loops[best.loop];
  const int n = static_cast<int>(loop.points.size());
  const Eigen::Vector2d& a = loop.points[bestSegment];
  const Eigen::Vector2d& b = loop.points[(bestSegment + 1) % n];
  const Eigen::Vector2d q = a + bestT * (b - a);
  if ((q - a).norm() <= 1e-6) {
    best.point = bestSegment;
  } else if ((q - b).norm() <= 1e-6) {
    best.point = (bestSegment + 1) % n;
  } else {
    best.point = bestSegment + 1;
    loop.points.insert(loop.points.begin() + best.point, q);
    loop.features.insert(loop.features.begin() + best.point, std::string());
  }
  return best;
}

// The corners of the traced outlines (before cuts), for snapping features onto them.
class CornerTargets {
 public:
  CornerTargets(const std::vector<ShapeLoop>& loops, double radius, double window) : radius_(radius) {
    if (radius <= 0) return;
    OutlineCornerOptions detection;
    detection.window = window;
    for (const ShapeLoop& l : loops) {
      const ArcLengthLoop loop(l.points);
      for (const OutlineCorner& c : outlineCorners(loop, detection)) corners_.push_back(loop.at(c.s));
    }
  }
  // The nearest corner within the radius of p, else p.
  Eigen::Vector2d target(const Eigen::Vector2d& p) const {
    Eigen::Vector2d best = p;
    double nearest = radius_;
    for (const Eigen::Vector2d& c : corners_)
      if ((c - p).norm() <= nearest) {
        nearest = (c - p).norm();
        best = c;
      }
    return best;
  }

 private:
  double radius_;
  std::vector<Eigen::Vector2d> corners_;
};

// The loop rotated to start at point `start`.
ShapeLoop rotated(const ShapeLoop& loop, int start) {
  ShapeLoop out = loop;
  std::rotate(out.points.begin(), out.points.begin() + start, out.points.end());
  std::rotate(out.features.begin(), out.features.begin() + start, out.features.end());
  return out;
}

void append(ShapeLoop& to, const Eigen::Vector2d& p, const std::string& feature = {}) {
  to.points.push_back(p);
  to.features.push_back(feature);
}

// Appends loop points [from, to) (no wrap).
void appendRange(ShapeLoop& to, const ShapeLoop& from, size_t begin, size_t end) {
  for (size_t i = begin; i < end; ++i) append(to, from.points[i], from.features[i]);
}

class CutApplier {
 public:
  CutApplier(std::vector<ShapeLoop>& loops, const CutSpec& cut, const std::string& where, double snapDistance)
      : loops_(loops), cut_(cut), where_(where), snapDistance_(snapDistance) {}

  void apply() {
    checkSelfCrossing();
    const bool startOnOutline = cut_.kind != CutKind::kSlit;
    const bool endOnOutline = cut_.kind == CutKind::kSplit;
    Snap start, end;
    Polyline pts = cut_.points;
    if (startOnOutline) {
      start = snapEnd(cut_.points.front(), "first");
      pts.front() = loops_[start.loop].points[start.point];
    }
    if (endOnOutline) {
      end = snapEnd(cut_.points.back(), "last");
      if (end.loop == start.loop && end.point < start.point) {
        // snapping the end may have inserted a point before the start: find the start again
        start.point = indexOf(start.loop, pts.front());
      }
      pts.back() = loops_[end.loop].points[end.point];
      if (end.loop == start.loop && end.point == start.point) throw error("starts and ends at the same outline point");
    }
    checkInside(pts, startOnOutline ? &start : nullptr, endOnOutline ? &end : nullptr);
    const std::vector<std::string> names = cutFeatureNames(cut_.name, cut_.kind);
    if (cut_.kind == CutKind::kNotch) notch(pts, start, names);
    if (cut_.kind == CutKind::kSplit) split(pts, start, end, names);
    if (cut_.kind == CutKind::kSlit) slit(pts, names);
  }

 private:
  InputError error(const std::string& what) const { return InputError(where_ + ": " + what); }

  int indexOf(int loop, const Eigen::Vector2d& p) const {
    const Polyline& pts = loops_[loop].points;
    return static_cast<int>(std::find(pts.begin(), pts.end(), p) - pts.begin());
  }

  Snap snapEnd(const Eigen::Vector2d& p, const std::string& which) {
    const Snap s = snapOntoLoops(loops_, p);
    if (s.distance > snapDistance_) {
      std::ostringstream msg;
      msg.precision(3);
      msg << "its " << which << " point " << formatPoint(p) << " must lie on the outline, but is " << s.distance
          << " px from it (at most " << snapDistance_ << " px)";
      throw error(msg.str());
    }
    const std::string& there = loops_[s.loop].features[s.point];
    if (!there.empty()) throw error("its " + which + " point lands on feature " + inQuotes(there) + "; move one of them");
    return s;
  }

  void checkSelfCrossing() const {
    const Polyline& c = cut_.points;
    for (size_t i = 0; i + 1 < c.size(); ++i)
      for (size_t j = i + 2; j + 1 < c.size(); ++j)
        if (segmentsMeet(c[i], c[i + 1], c[j], c[j + 1]))
          throw error("crosses itself (segments " + std::to_string(i + 1) + " and " + std::to_string(j + 1) + ")");
  }

  // Every cut segment stays inside the shape: it meets no outline segment except, at a snapped
  // end, the two outline segments at that end.
  void checkInside(const Polyline& pts, const Snap* start, const Snap* end) const {
    const auto incident = [&](const Snap* s, size_t l, size_t i, size_t n) {
      return s && static_cast<int>(l) == s->loop &&
             (static_cast<int>(i) == s->point || static_cast<int>((i + 1) % n) == s->point);
    };
    for (size_t k = 0; k + 1 < pts.size(); ++k)
      for (size_t l = 0; l < loops_.size(); ++l) {
        const Polyline& loop = loops_[l].points;
        for (size_t i = 0, n = loop.size(); i < n; ++i) {
          if (k == 0 && incident(start, l, i, n)) continue;
          if (k + 2 == pts.size() && incident(end, l, i, n)) continue;
          if (segmentsMeet(pts[k], pts[k + 1], loop[i], loop[(i + 1) % n]))
            throw error("leaves the shape: its segment from point " + std::to_string(k + 1) + " to point " +
                        std::to_string(k + 2) + " crosses the outline at " +
                        formatPoint(meetingPoint(pts[k], pts[k + 1], loop[i], loop[(i + 1) % n])));
        }
      }
    const Eigen::Vector2d probe = 0.5 * (pts[0] + pts[1]);
    int crossings = 0;
    for (const ShapeLoop& loop : loops_) crossings += rayCrossings(loop.points, probe);
    if (crossings % 2 == 0)
      throw error("leaves the shape: it runs outside the drawing from point 1 " + formatPoint(pts[0]));
  }

  void notch(const Polyline& pts, const Snap& mouth, const std::vector<std::string>& names) {
    // names: left, right, tip. Walking the loop into the notch meets its right side first.
    const ShapeLoop old = rotated(loops_[mouth.loop], mouth.point);
    ShapeLoop out;
    append(out, pts.front(), names[1]);
    for (size_t i = 1; i + 1 < pts.size(); ++i) append(out, pts[i]);
    append(out, pts.back(), names[2]);
    for (size_t i = pts.size() - 2; i >= 1; --i) append(out, pts[i]);
    append(out, pts.front(), names[0]);
    appendRange(out, old, 1, old.points.size());
    loops_[mouth.loop] = std::move(out);
  }

  void split(const Polyline& pts, const Snap& start, const Snap& end, const std::vector<std::string>& names) {
    // names: start.left, start.right, end.left, end.right. The right side runs start -> end.
    const auto rightSide = [&](ShapeLoop& out) {
      append(out, pts.front(), names[1]);
      for (size_t i = 1; i + 1 < pts.size(); ++i) append(out, pts[i]);
      append(out, pts.back(), names[3]);
    };
    const auto leftSide = [&](ShapeLoop& out) {
      append(out, pts.back(), names[2]);
      for (size_t i = pts.size() - 2; i >= 1; --i) append(out, pts[i]);
      append(out, pts.front(), names[0]);
    };
    if (start.loop == end.loop) {  // separates one loop into two
      const ShapeLoop old = rotated(loops_[start.loop], start.point);
      const int n = static_cast<int>(old.points.size());
      const int e = ((end.point - start.point) % n + n) % n;
      ShapeLoop first, second;
      rightSide(first);
      appendRange(first, old, e + 1, n);
      leftSide(second);
      appendRange(second, old, 1, e);
      loops_[start.loop] = std::move(first);
      loops_.push_back(std::move(second));
      return;
    }
    const ShapeLoop a = rotated(loops_[start.loop], start.point);
    const ShapeLoop b = rotated(loops_[end.loop], end.point);
    ShapeLoop joined;  // joins two loops into one
    rightSide(joined);
    appendRange(joined, b, 1, b.points.size());
    leftSide(joined);
    appendRange(joined, a, 1, a.points.size());
    loops_[start.loop] = std::move(joined);
    loops_.erase(loops_.begin() + end.loop);
  }

  void slit(const Polyline& pts, const std::vector<std::string>& names) {
    // names: start, end. A new loop around both sides of the cut.
    ShapeLoop hole;
    append(hole, pts.front(), names[0]);
    for (size_t i = 1; i + 1 < pts.size(); ++i) append(hole, pts[i]);
    append(hole, pts.back(), names[1]);
    for (size_t i = pts.size() - 2; i >= 1; --i) append(hole, pts[i]);
    loops_.push_back(std::move(hole));
  }

  std::vector<ShapeLoop>& loops_;
  const CutSpec& cut_;
  std::string where_;
  double snapDistance_;
};


}  // namespace

std::pair<double, Eigen::Vector2d> distanceToLoops(const std::vector<ShapeLoop>& loops, const Eigen::Vector2d& p) {
  std::pair<double, Eigen::Vector2d> best{std::numeric_limits<double>::infinity(), p};
  for (const ShapeLoop& loop : loops)
    for (size_t i = 0, n = loop.points.size(); i < n; ++i) {
      const Eigen::Vector2d& a = loop.points[i];
      const Eigen::Vector2d& b = loop.points[(i + 1) % n];
      const Eigen::Vector2d q = a + closestParameter(a, b, p) * (b - a);
      if ((q - p).norm() < best.first) best = {(q - p).norm(), q};
    }
  return best;
}

void checkInteriorFeatures(const Scene& scene, int key, const std::vector<Outline>& outlines, const KeyShape& shape,
                           double margin) {
  const KeySpec& spec = scene.keys.at(key);
  const std::string where = std::filesystem::path(scene.file).filename().string() + ": key " + inQuotes(spec.name);
  for (const auto& [name, p] : spec.interiorFeatures) {
    const std::string what = where + ": interior feature " + inQuotes(name) + " at " + formatPoint(p);
    int crossings = 0;  // odd: inside the shape (outer loops and holes together)
    bool inPiece = false;
    for (const Outline& o : outlines) {
      const bool inOuter = rayCrossings(o.outer, p) % 2 == 1;
      inPiece = inPiece || inOuter;
      crossings += inOuter;
      for (const Polyline& h : o.holes) crossings += rayCrossings(h, p) % 2;
    }
    if (crossings % 2 == 0)
      throw InputError(what + (inPiece ? " lies in a hole of the drawing" : " lies outside the drawn shape") +
                       ": interior features are points inside the shape, placed on the drawing in every key "
                       "(a point on the outline is a \"features\" entry)");
    const double radius = spec.interiorRadii.count(name) ? spec.interiorRadii.at(name) : 0.0;
    const auto [distance, nearest] = distanceToLoops(shape.loops, p);
    if (distance < margin + radius) {
      std::ostringstream msg;
      msg.precision(3);
      msg << what << " is " << distance << " px from the outline or a cut (at " << formatPoint(nearest)
          << "); an interior feature needs at least " << margin + radius;
      if (radius > 0)
        msg << " px (its radius " << radius << " and one edge length): move it further inside, make its radius smaller, or "
               "lower edge_length";
      else
        msg << " px (one edge length): move it further inside, make it a \"features\" entry on the outline, or lower "
               "edge_length";
      throw InputError(msg.str());
    }
    for (const auto& [other, q] : spec.interiorFeatures) {
      const double apart = 1 + radius + (spec.interiorRadii.count(other) ? spec.interiorRadii.at(other) : 0.0);
      if (other < name && (q - p).norm() < apart) {
        std::ostringstream msg;
        msg.precision(3);
        msg << where << ": interior features " << inQuotes(other) << " and " << inQuotes(name) << " are less than " << apart
            << " px apart at " << formatPoint(p)
            << (apart > 1 ? " (their radii and 1 px): place them apart, make their radii smaller, or drop one"
                          : ": place them apart, or drop one");
        throw InputError(msg.str());
      }
    }
  }
}

std::pair<int, int> findFeature(const KeyShape& shape, const std::string& feature) {
  for (size_t l = 0; l < shape.loops.size(); ++l) {
    const auto& f = shape.loops[l].features;
    const auto it = std::find(f.begin(), f.end(), feature);
    if (it != f.end()) return {static_cast<int>(l), static_cast<int>(it - f.begin())};
  }
  return {-1, -1};
}

KeyShape buildKeyShape(const Scene& scene, int key, const std::vector<Outline>& outlines,
                       const KeyShapeOptions& options) {
  const KeySpec& spec = scene.keys.at(key);
  const std::string where = std::filesystem::path(scene.file).filename().string() + ": key " + inQuotes(spec.name);
  KeyShape shape;
  shape.key = spec.name;
  for (const Outline& o : outlines) {
    shape.loops.push_back({o.outer, std::vector<std::string>(o.outer.size())});
    for (const Polyline& h : o.holes) shape.loops.push_back({h, std::vector<std::string>(h.size())});
  }
  const CornerTargets corners(shape.loops, options.cornerSnap, options.cornerWindow);
  for (const auto& [name, p] : spec.features) {
    Snap s = snapOntoLoops(shape.loops, corners.target(p));
    if (!shape.loops[s.loop].features[s.point].empty()) s = snapOntoLoops(shape.loops, p);  // the corner is taken
    if (s.distance > options.snapDistance) {
      std::ostringstream msg;
      msg.precision(3);
      msg << where << ": feature " << inQuotes(name) << " at " << formatPoint(p) << " is " << s.distance
          << " px from the outline (at most " << options.snapDistance << " px)";
      throw InputError(msg.str());
    }
    std::string& there = shape.loops[s.loop].features[s.point];
    if (!there.empty())
      throw InputError(where + ": features " + inQuotes(there) + " and " + inQuotes(name) + " land on the same outline point " +
                       formatPoint(shape.loops[s.loop].points[s.point]));
    there = name;
  }
  for (const CutSpec& cut : spec.cuts)
    CutApplier(shape.loops, cut, where + ": cut " + inQuotes(cut.name), options.snapDistance).apply();
  return shape;
}

}  // namespace ib
