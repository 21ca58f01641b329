// Outlines matched by what they look like (../shared/correspondence.md): between two knots (the
// features, and the corners every key has), a key's outline is matched to the reference key's by
// dynamic programming over both sampled evenly, on position (a robust cost: far-apart points all
// cost the same) and, between near points, tangent, instead of by arc length alone. Where two keys' outlines coincide their
// points then correspond, and a part that moved (a tail) does not drag the rest along the outline.
// Internal to matchBoundaries (shared_boundary.h).
#pragma once

#include "meshing/shared_boundary.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

struct OutlineMatchOptions {
  // px: two points this far apart cost half as much as points far apart; the cost d^2 / (d^2 + scale^2)
  // is sharp near 0 and the same for every point of a part that moved. Default 2.
  double scale = 2;
  // Cost of opposite tangents between points at the same place, against 1 for points far apart
  // (scaled by how near they are: d^2 / (d^2 + scale^2) less). Default 1.
  double tangentWeight = 1;
  double stepPenalty = 0.05;  // cost of each step off arc length (a (1, 2) or (2, 1) step). Default 0.05.
  double spacing = 1;         // px: the samples' spacing along the longer arc (at most maxSamples). Default 1.
  int maxSamples = 800;       // samples per arc and key at most. Default 800.
};

// For `reference` and `key`, two open polylines sampled at the same count n >= 2 whose ends
// correspond: for every reference sample i, the matching position along `key` as a fraction of its
// samples in [0, 1], increasing from 0 to 1. The match advances between half and twice as fast as
// arc length (steps (1, 1), (1, 2), (2, 1)), so no stretch of one outline maps to a point of the other.
std::vector<double> matchByShape(const std::vector<Eigen::Vector2d>& reference, const std::vector<Eigen::Vector2d>& key,
                                 const OutlineMatchOptions& options = {});

// Adds knots (SharedBoundary: corners of no key) along every arc but cut sides, between the knots
// it has, where the keys' outlines match the reference key's by shape (matchByShape), about every
// two edge lengths of the reference's outline.
void placeShapeKnots(SharedBoundary& boundary, int reference, const SharedBoundaryOptions& options);

// Adds options.artworkKnots as knots held in every key (SharedBoundaryOptions::artworkKnots says
// which are kept), before the shape knots are placed between the knots.
void placeArtworkKnots(SharedBoundary& boundary, const SharedBoundaryOptions& options);

}  // namespace ib
