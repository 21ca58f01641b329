// Corners of a traced outline: where it turns sharply within a short stretch (docs/solver.md,
// "Corners"). The shared boundary puts a vertex at every corner so that no key's mesh boundary
// cuts across one, and pairs corners that clearly correspond between keys.
#pragma once

#include "core/plane_geometry.h"

#include <Eigen/Core>
#include <limits>

#include <vector>

namespace ib {

struct OutlineCorner {
  double s = 0;     // px: arc length along the loop from its point 0
  double turn = 0;  // radians: signed turning there, > 0 convex (the shape lies to the left)
};

struct OutlineCornerOptions {
  // px: half the stretch over which the turning is measured; a bend spread over more than this
  // is a curve, not a corner. Default 4 (the shared boundary passes the edge length).
  double window = 4;
  // radians: least turning over the window for a corner. Default 22 degrees.
  double minimumTurn = 0.38;
  // Share of the turning that must happen within a third of the window: a corner is a bend that
  // stays sharp when looked at more closely, a tight curve is not. Default 0.6.
  double concentration = 0.6;
};

// The loop's corners, by increasing s; none closer than one window to each other.
std::vector<OutlineCorner> outlineCorners(const ArcLengthLoop& loop, const OutlineCornerOptions& options);

// A corner of one key's stretch of outline between two features (an arc).
struct ArcCorner {
  double fraction = 0;  // of the arc's length in that key, in (0, 1)
  double turn = 0;      // radians, > 0 convex
  // px: the corner in the reference key's frame, through the least-squares affine map of the
  // key's loop onto the reference's (a squash or a stretch undone). NaN: not known, or the key is
  // no such map of the reference (a wing that flaps); corners then pair by fraction and turning.
  Eigen::Vector2d place = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
};

struct CornerMatchOptions {
  // Cost of leaving a corner unpaired, against pairing cost |fraction difference| + half the
  // turning difference over pi + their distance (ArcCorner) over the reference's arc length
  // (same-signed corners only). Default 0.15: corners pair when they lie within about 30% of the
  // arc of each other, about as far in the plane, and turn alike.
  double unpairedCost = 0.15;
  // px: least arc length between consecutive knots in every key. Default 1.
  double minimumGap = 1;
  // px: an unpaired corner this close to a knot (in its own key) moves that knot onto itself in
  // its key instead of adding one. Default 4 (the shared boundary passes the edge length).
  double mergeDistance = 4;
  // Whether the corners left unpaired become knots too (held in their own key only). Default true.
  bool unpaired = true;
};

// A place along an arc that gets a boundary vertex in every key.
struct CornerKnot {
  std::vector<double> fractions;  // [key]: of the arc's length in that key
  std::vector<char> corner;       // [key]: it is a corner of that key's outline (the vertex stays there)
};

// The arc's knots, increasing along the arc in every key. First every corner of the reference key
// paired (in order, by least total cost) with a corner of every other key, at those corners (a
// corner in every key); then every other corner of every key, at the same place relative to the
// paired knots in the keys that lack it (a corner in that key only). `corners` [key], each by
// increasing fraction; `lengths` [key] the arc's length (px).
std::vector<CornerKnot> cornerKnots(const std::vector<std::vector<ArcCorner>>& corners,
                                             const std::vector<double>& lengths, int reference,
                                             const CornerMatchOptions& options);

}  // namespace ib
