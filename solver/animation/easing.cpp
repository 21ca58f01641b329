#include "animation/easing.h"

#include "core/error.h"
#include "core/suggest.h"

#include <algorithm>
#include <cmath>

namespace ib {

namespace {

// One coordinate of the cubic Bezier from 0 through p1, p2 to 1 at parameter t.
double bezierCoordinate(double p1, double p2, double t) {
  const double s = 1 - t;
  return 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t;
}

double bezierSlope(double p1, double p2, double t) {
  const double s = 1 - t;
  return 3 * s * s * p1 + 6 * s * t * (p2 - p1) + 3 * t * t * (1 - p2);
}

// y at the parameter t where x(t) = u. x is non-decreasing in t when x1, x2 are in [0, 1], so a
// bracketed Newton iteration (bisection when Newton leaves the bracket) always converges.
double cubicBezierTiming(const Eigen::Vector4d& c, double u) {
  double lo = 0, hi = 1, t = u;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double error = bezierCoordinate(c(0), c(2), t) - u;
    if (std::abs(error) < 1e-14) break;
    (error > 0 ? hi : lo) = t;
    const double slope = bezierSlope(c(0), c(2), t);
    double next = slope > 1e-12 ? t - error / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo < 1e-15) break;
    t = next;
  }
  return std::clamp(bezierCoordinate(c(1), c(3), t), 0.0, 1.0);
}

}  // namespace

std::string easingName(EaseKind kind) {
  switch (kind) {
    case EaseKind::kLinear: return "linear";
    case EaseKind::kEaseIn: return "ease-in";
    case EaseKind::kEaseOut: return "ease-out";
    case EaseKind::kEaseInOut: return "ease-in-out";
    case EaseKind::kHold: return "hold";
    case EaseKind::kCubicBezier: return "cubic-bezier";
  }
  return "?";
}

Easing namedEasing(const std::string& name, const std::string& where) {
  Easing e;
  if (name == "linear") return e;
  if (name == "hold") {
    e.kind = EaseKind::kHold;
    return e;
  }
  if (name == "ease-in") {
    e.kind = EaseKind::kEaseIn;
    e.bezier = {0.42, 0, 1, 1};
  } else if (name == "ease-out") {
    e.kind = EaseKind::kEaseOut;
    e.bezier = {0, 0, 0.58, 1};
  } else if (name == "ease-in-out") {
    e.kind = EaseKind::kEaseInOut;
    e.bezier = {0.42, 0, 0.58, 1};
  } else {
    throw InputError(where + inQuotes(name) +
                     " is not an easing (linear, ease-in, ease-out, ease-in-out, hold, or {\"cubic_bezier\": [x1, y1, x2, y2]})" +
                     didYouMean(name, {"linear", "ease-in", "ease-out", "ease-in-out", "hold"}));
  }
  return e;
}

Easing cubicBezierEasing(const Eigen::Vector4d& controls, const std::string& where) {
  for (int i = 0; i < 4; ++i)
    if (!(controls(i) >= 0 && controls(i) <= 1))
      throw InputError(where + "cubic_bezier: every coordinate must be in [0, 1] (so the curve is a function of time "
                               "and weights stay convex)");
  Easing e;
  e.kind = EaseKind::kCubicBezier;
  e.bezier = controls;
  return e;
}

double ease(const Easing& easing, double u) {
  if (!(u > 0)) return 0;
  if (u >= 1) return 1;
  switch (easing.kind) {
    case EaseKind::kLinear: return u;
    case EaseKind::kHold: return 0;
    default: return cubicBezierTiming(easing.bezier, u);
  }
}

}  // namespace ib
