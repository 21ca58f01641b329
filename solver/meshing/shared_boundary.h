// Boundary correspondence across keys (docs/design.md, "The scene model"): every key's loops are
// matched to the reference key's, cut into arcs at the features, and every arc gets the same
// number of boundary edges in every key, spaced by arc length.
#pragma once

#include "core/plane_geometry.h"
#include "meshing/key_shape.h"
#include "meshing/outline_corners.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ib {

// A feature-to-feature stretch of one reference loop (a whole loop when it has one feature or
// none). Arcs of a cut's two sides are partners: collocated, reversed, in the keys that close it.
struct BoundaryArc {
  int loop = 0;               // reference loop index
  int indexInLoop = 0;        // its place among the loop's arcs, in walking order
  std::string from, to;       // features at its ends; "" for a featureless loop's aligned start
  int segments = 1;           // boundary edges along it, the same in every key
  int partner = -1;           // the arc along the other side of the same cut, or -1
  std::vector<int> closedIn;  // keys where this arc and its partner are collocated
  // Fractions u in (0, 1), increasing, of the arc's corner vertices (multiples of 1 / segments):
  // where some key's outline has a corner (SharedBoundaryOptions::corners). Empty for cut sides.
  std::vector<double> knots;
  std::vector<std::vector<char>> knotCornerIn;  // [knot][key]: the knot is a corner of that key's outline
};

// One key's loops in reference loop order, each parametrized by arc length, with the arc length
// at which each of its arcs starts.
struct KeyBoundary {
  std::vector<ArcLengthLoop> loops;
  std::vector<std::vector<double>> arcStarts;  // [loop][i]: start of the loop's i-th arc
  // [arc][knot]: where each of the arc's knots lies in this key, as a fraction of the arc's length
  // here; between knots, fractions of u map linearly.
  std::vector<std::vector<double>> knotFractions;
};


struct SharedBoundaryOptions {
  double edgeLength = 8;  // px: longest boundary edge in any key (arcs are split to fit). Default 8.
  int alignmentSamples = 64;  // samples per loop for the automatic start of featureless loops. Default 64.
  // Outline corners: detected over a window of one edge length, paired with the default
  // CornerMatchOptions, unpaired ones merged within one edge length. Default vertices: every
  // corner of every key is a boundary vertex (held on it in its own key).
  CornerHandling corners = CornerHandling::kVertices;
  // px: farthest any key's outline may stray from its boundary edges (the chords between
  // consecutive boundary vertices): arcs get more segments where they curve. Default 0.3, so
  // that each key's silhouette follows its drawing within half a pixel.
  double chordTolerance = 0.3;
  // Between features and paired corners: arc length (the paper), or the outlines matched by shape
  // (outline_matching.h). Default outline.
  OutlineCorrespondence correspondence = OutlineCorrespondence::kOutline;
  // With kArtwork: no shape knot within shapeKnotClearance px of these points (px, in any key),
  // where a key folded before; the outlines there follow arc length between the knots around.
  // Default none.
  std::vector<Eigen::Vector2d> shapeKnotsClearOf = {};
  double shapeKnotClearance = 0;  // px; default 0
  // With kArtwork: points that correspond, [knot][key] (px, on or near each key's outline), such
  // as where a stripe drawn across the shape meets the outline in every key
  // (ArtworkRegions::contacts). Each becomes a knot held in every key where it lies on the same arc
  // in every key, in the same order among the arc's knots, at least an edge length from them and
  // from the arc's ends; the others are left out. Default none.
  std::vector<std::vector<Eigen::Vector2d>> artworkKnots = {};
};

struct SharedBoundary {
  std::vector<BoundaryArc> arcs;             // in loop order, each loop's arcs in walking order
  std::vector<std::vector<int>> loopArcs;    // [loop]: indices into arcs
  std::vector<KeyBoundary> keys;             // [key]

  double arcLength(int key, int arc) const;
  // Fraction of arc `arc`'s length in key `key` at u in [0, 1] (u itself on an arc without knots).
  double fraction(int key, int arc, double u) const;
  // The index of arc `arc`'s knot at u, or -1.
  int knotAt(int arc, double u) const;
  // The point of key `key` at u in [0, 1] along arc `arc`.
  Eigen::Vector2d at(int key, int arc, double u) const;
  // The point of key `key` at fraction f in [0, 1] of arc `arc`'s length there (at: f = fraction(key, arc, u)).
  Eigen::Vector2d atFraction(int key, int arc, double f) const;
  // Largest distance of key `key`'s outline between u0 <= u1 <= u2 along arc `arc` from
  // the chords u0 -> u1 and u1 -> u2 between their points (px); u1 = u2 for a single chord.
  double chordDeviation(int key, int arc, double u0, double u1, double u2) const;
};

// Matches the keys' loops to the reference key's. Every featured loop must carry the same
// features in the same cyclic order in every key; featureless loops are paired, pieces with pieces
// and holes with holes, by nearest centroid and size, and started where an affine map of
// arc-length samples fits best (ties to the least rotation). Throws InputError naming the file and the keys: for features that
// differ, which ones and on which piece or hole; for an extra hole or piece in one key, where it is
// and the cut (split, slit) or drawing fix that makes the topology match; for pairings about as good
// either way round, that features must say which loop becomes which.
SharedBoundary matchBoundaries(const Scene& scene, const std::vector<KeyShape>& shapes,
                               const SharedBoundaryOptions& options);

// A loop for messages: its kind, bounding-box centre and area in drawing pixels, e.g.
// "hole around (64, 64), 1520 px²" (a slit's loop, of zero area, is a "slit").
std::string describeLoop(const Polyline& loop);

}  // namespace ib
