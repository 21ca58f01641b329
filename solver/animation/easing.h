// Timing curves for a timeline segment: e(u) maps the fraction u in [0, 1] of a segment's time to
// the fraction of the way from its start pose to its end pose. Every curve stays in [0, 1] (so
// blended weights stay convex), starts at e(0) = 0 and ends at e(1) = 1 exactly.
#pragma once

#include <Eigen/Core>
#include <string>

namespace ib {

enum class EaseKind {
  kLinear,       // e(u) = u
  kEaseIn,       // cubic-bezier(0.42, 0, 1, 1): starts at zero slope
  kEaseOut,      // cubic-bezier(0, 0, 0.58, 1): ends at zero slope
  kEaseInOut,    // cubic-bezier(0.42, 0, 0.58, 1): zero slope at both ends
  kHold,         // e(u) = 0 for u < 1: the start pose is held, then the end pose (stepped keys)
  kCubicBezier,  // CSS cubic-bezier(x1, y1, x2, y2) with every coordinate in [0, 1]
};

struct Easing {
  EaseKind kind = EaseKind::kLinear;
  // Control points (x1, y1, x2, y2) of the timing curve from (0, 0) to (1, 1); used by kCubicBezier
  // and set to the preset's values for kEaseIn, kEaseOut and kEaseInOut.
  Eigen::Vector4d bezier{0, 0, 1, 1};
};

// A named curve: "linear", "ease-in", "ease-out", "ease-in-out" or "hold". Throws InputError
// listing the names for anything else; `where` prefixes the message.
Easing namedEasing(const std::string& name, const std::string& where);

// A cubic-bezier curve; throws InputError (prefixed by `where`) unless every coordinate is in [0, 1].
Easing cubicBezierEasing(const Eigen::Vector4d& controls, const std::string& where);

// e(u) for u in [0, 1] (u is clamped). Deterministic: the same u gives the same bits.
double ease(const Easing& easing, double u);

// The name used in files and messages ("ease-in", "cubic-bezier", ...).
std::string easingName(EaseKind kind);

}  // namespace ib
