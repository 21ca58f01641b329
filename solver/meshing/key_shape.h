// A key's shape as the multimesh sees it (docs/design.md, "The scene model"): the traced outlines
// with the key's features snapped onto them, cut open along the key's own cuts. After cutting,
// every key of a scene must have the same loops with the same features in the same order.
#pragma once

#include "meshing/tracing.h"
#include "scene/scene.h"

#include <string>
#include <utility>
#include <vector>

namespace ib {

// One boundary loop: the shape lies to the left of every edge in a y-up frame, so an outer loop
// has positive loopArea, a hole negative, and a slit's loop (both sides of one cut) zero.
struct ShapeLoop {
  Polyline points;
  std::vector<std::string> features;  // per point: the feature there, or "" (same size as points)
};

struct KeyShape {
  std::string key;
  std::vector<ShapeLoop> loops;
};

struct KeyShapeOptions {
  // px: the farthest a placed feature or a cut's boundary end may lie from the outline; both are
  // snapped to the nearest outline point. Default 8.
  double snapDistance = 8;
  // px: a placed feature this close to a corner of the traced outline (a sharp turn,
  // meshing/outline_corners.h) lands on the corner instead: a feature placed at a star's tip means
  // the tip, wherever the drawing's stroke puts it (a cut's ends take the plain nearest point).
  // 0: plain nearest point. Default 4.
  double cornerSnap = 4;
  // px: the window of that corner detection (OutlineCornerOptions::window): a stroke's rounded
  // tip is a corner at 8 px, a curve at 4. Default 8.
  double cornerWindow = 8;
};

// Snaps key `key`'s placed features onto `outlines` (its traced drawing; onto a corner within
// options.cornerSnap, else the nearest point), then applies its cuts in
// file order: a notch walks into the shape and back (NAME.right, the tip, NAME.left), a split
// joins or separates loops, a slit adds a loop of both its sides. Cut sides are exact copies of
// the cut's points. Throws InputError naming file, key, feature or cut: a feature or cut end too
// far from the outline, two features on one point, a cut that leaves the shape or crosses itself.
KeyShape buildKeyShape(const Scene& scene, int key, const std::vector<Outline>& outlines,
                       const KeyShapeOptions& options);

// Distance from p to the nearest point of any of `loops` (outlines and cut sides, px), and that point.
std::pair<double, Eigen::Vector2d> distanceToLoops(const std::vector<ShapeLoop>& loops, const Eigen::Vector2d& p);

// Checks key `key`'s interior features against its traced drawing and shape (after cuts): each
// must lie inside the shape (not in a hole, not outside), at least `margin` px from every loop
// (outline, holes, cut sides), and at least 1 px from the key's other interior features, so that
// it can be a mesh vertex pinned in every key. Throws InputError naming file, key and feature.
void checkInteriorFeatures(const Scene& scene, int key, const std::vector<Outline>& outlines, const KeyShape& shape,
                           double margin);

// Index of the loop and point carrying `feature`, or {-1, -1}.
std::pair<int, int> findFeature(const KeyShape& shape, const std::string& feature);

}  // namespace ib
