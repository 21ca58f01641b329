// The shared boundary's sampling (docs/drawings-to-multimesh.md, "Corners" and "Edge length"):
// knots at the outline corners every key has, then how many boundary edges every arc gets.
// Internal to matchBoundaries.
#pragma once

#include "meshing/shared_boundary.h"

namespace ib {

// Finds every key's outline corners and fills BoundaryArc::knotCornerIn and
// KeyBoundary::knotFractions (knot u values come with the segment counts).
void placeCornerKnots(SharedBoundary& boundary, int reference, const SharedBoundaryOptions& options);

// More knots (corners of no key, free to slide) where an arc curves: between them, even chords
// follow every key's outline within options.chordTolerance (px) at options.edgeLength.
void placeCurveKnots(SharedBoundary& boundary, const SharedBoundaryOptions& options);

// BoundaryArc::segments and knots: enough segments between knots that no key's boundary edge is
// longer than `edgeLength` (px); cut sides equal; at least three per loop.
void countSegments(SharedBoundary& boundary, int reference, double edgeLength);

}  // namespace ib
