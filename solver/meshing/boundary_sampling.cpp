#include "meshing/boundary_sampling.h"

#include <algorithm>
#include <cmath>

namespace ib {

// Knots at the keys' outline corners (outline_corners.h), on every arc but cut sides (which
// must stay copies of each other) and away from the arc's ends (features give vertices there).
void placeCornerKnots(SharedBoundary& boundary, int reference, const SharedBoundaryOptions& options) {
  const int keys = static_cast<int>(boundary.keys.size());
  for (KeyBoundary& kb : boundary.keys) kb.knotFractions.assign(boundary.arcs.size(), {});
  if (options.corners == CornerHandling::kOff) return;
  OutlineCornerOptions detection;
  detection.window = options.edgeLength;
  CornerMatchOptions matching;
  matching.unpaired = options.corners == CornerHandling::kVertices;
  matching.mergeDistance = options.edgeLength;
  std::vector<std::vector<std::vector<OutlineCorner>>> found(keys);  // [key][loop]
  for (int k = 0; k < keys; ++k)
    for (const ArcLengthLoop& loop : boundary.keys[k].loops) found[k].push_back(outlineCorners(loop, detection));
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    const BoundaryArc& arc = boundary.arcs[a];
    if (arc.partner >= 0) continue;
    std::vector<std::vector<ArcCorner>> corners(keys);
    std::vector<double> lengths(keys);
    for (int k = 0; k < keys; ++k) {
      const KeyBoundary& kb = boundary.keys[k];
      const double loopLength = kb.loops[arc.loop].length(), start = kb.arcStarts[arc.loop][arc.indexInLoop];
      lengths[k] = boundary.arcLength(k, static_cast<int>(a));
      for (const OutlineCorner& c : found[k][arc.loop]) {
        const double along = std::fmod(c.s - start + 2 * loopLength, loopLength);
        if (along >= detection.window && along <= lengths[k] - detection.window)
          corners[k].push_back({along / lengths[k], c.turn});
      }
      std::sort(corners[k].begin(), corners[k].end(),
                [](const ArcCorner& x, const ArcCorner& y) { return x.fraction < y.fraction; });
    }
    const std::vector<CornerKnot> knots = cornerKnots(corners, lengths, reference, matching);
    for (const CornerKnot& knot : knots) {
      boundary.arcs[a].knotCornerIn.push_back(knot.corner);
      for (int k = 0; k < keys; ++k) boundary.keys[k].knotFractions[a].push_back(knot.fractions[k]);
    }
  }
}

// Enough segments that no key's boundary edge is longer than the edge length, counted between
// knots; partners equal; at least three per loop. Knots then sit at multiples of 1 / segments.
void countSegments(SharedBoundary& boundary, int reference, double edgeLength) {
  std::vector<std::vector<int>> pieces(boundary.arcs.size());  // [arc]: segments between consecutive knots
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    const size_t knots = boundary.keys[reference].knotFractions[a].size();
    for (size_t j = 0; j <= knots; ++j) {
      double longest = 0;
      for (size_t k = 0; k < boundary.keys.size(); ++k) {
        const std::vector<double>& f = boundary.keys[k].knotFractions[a];
        const double span = (j < knots ? f[j] : 1) - (j > 0 ? f[j - 1] : 0);
        longest = std::max(longest, span * boundary.arcLength(static_cast<int>(k), static_cast<int>(a)));
      }
      pieces[a].push_back(std::max(1, static_cast<int>(std::ceil(longest / edgeLength - 1e-9))));
    }
  }
  const auto total = [&](size_t a) {
    int sum = 0;
    for (int p : pieces[a]) sum += p;
    return sum;
  };
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    const int partner = boundary.arcs[a].partner;  // cut sides have no knots: one piece each
    if (partner >= 0) pieces[a][0] = pieces[partner][0] = std::max(pieces[a][0], pieces[partner][0]);
  }
  for (const std::vector<int>& loop : boundary.loopArcs) {
    int sum = 0;
    for (int a : loop) sum += total(a);
    for (size_t i = 0; sum < 3; ++i, ++sum) {
      const int a = loop[i % loop.size()];
      ++pieces[a].back();
      if (boundary.arcs[a].partner >= 0) pieces[boundary.arcs[a].partner].back() = pieces[a].back();
    }
  }
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    BoundaryArc& arc = boundary.arcs[a];
    arc.segments = total(a);
    int upTo = 0;
    for (size_t j = 0; j + 1 < pieces[a].size(); ++j) {
      upTo += pieces[a][j];
      arc.knots.push_back(static_cast<double>(upTo) / arc.segments);
    }
  }
}

}  // namespace ib
