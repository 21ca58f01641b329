#include "meshing/boundary_sampling.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ib {

namespace {

// Largest RMS distance of a loop's fit from the reference's loop, over the reference loop's RMS
// radius, for the fit to say where corners are: a squash or a stretch fits within it
// (chick-squash 0.07); two mirrored leans (lean-mirror 0.15), a wing that flaps or a tail that
// swings (0.15 to 0.30 on the drawn bat, tail, leg and cat-tail) do not, and there the corners'
// places say nothing that their order along the outline does not.
constexpr double kSquashFit = 0.1;

// The least-squares affine map (x -> A x + t, px) of key k's loop onto the reference key's, fitted
// on 32 points per arc at the same fractions of the arc's length in both (the arcs' ends, features
// or the loops' aligned starts, correspond); none when it does not fit within kSquashFit.
std::optional<Eigen::Affine2d> loopFit(const SharedBoundary& boundary, int k, int reference, int loop) {
  constexpr int kPerArc = 32;
  Polyline from, to;
  for (int a : boundary.loopArcs[loop])
    for (int i = 0; i < kPerArc; ++i) {
      const double f = static_cast<double>(i) / kPerArc;
      from.push_back(boundary.atFraction(k, a, f));
      to.push_back(boundary.atFraction(reference, a, f));
    }
  const std::optional<AffineFit> fit = affineFit(from, to);
  if (!fit || fit->residual >= kSquashFit * kSquashFit * fit->toSpread) return std::nullopt;
  Eigen::Affine2d map = Eigen::Affine2d::Identity();
  map.linear() = fit->linear;
  map.translation() = fit->translation;
  return map;
}

Eigen::Vector2d placed(const std::optional<Eigen::Affine2d>& fit, const Eigen::Vector2d& p) {
  return fit ? Eigen::Vector2d(*fit * p) : Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace

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
  std::vector<std::vector<std::optional<Eigen::Affine2d>>> fits(keys);  // [key][loop]: onto the reference's frame
  for (int k = 0; k < keys; ++k)
    for (size_t l = 0; l < boundary.keys[k].loops.size(); ++l) {
      found[k].push_back(outlineCorners(boundary.keys[k].loops[l], detection));
      fits[k].push_back(k == reference ? std::optional<Eigen::Affine2d>(Eigen::Affine2d::Identity())
                                       : loopFit(boundary, k, reference, static_cast<int>(l)));
    }
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
          corners[k].push_back({along / lengths[k], c.turn, placed(fits[k][arc.loop], kb.loops[arc.loop].at(c.s))});
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

namespace {

// One key's stretch of an arc between two consecutive knots, as fractions of the arc's length there.
struct Piece {
  std::vector<double> from, to;  // [key]
};

// Where a piece strays most from its even chords (as many in every key as the edge length asks
// of the longest): the largest distance over keys (px) and where, as a fraction of the piece.
struct Stray {
  double distance = 0;
  double at = 0.5;
};

// The arc length between s0 < s1 of key loop `loop` farthest from the chord at(s0) -> at(s1),
// looked for every 0.25 px (or 64 steps on a shorter chord).
double farthestFromChord(const ArcLengthLoop& loop, double s0, double s1) {
  const Eigen::Vector2d a = loop.at(s0), b = loop.at(s1);
  const int steps = std::max(64, static_cast<int>(std::ceil((s1 - s0) / 0.25)));
  double best = 0, where = 0.5 * (s0 + s1);
  for (int i = 1; i < steps; ++i) {
    const double s = s0 + (s1 - s0) * i / steps;
    const Eigen::Vector2d p = loop.at(s);
    const double d = (a + closestParameter(a, b, p) * (b - a) - p).squaredNorm();
    if (d > best) best = d, where = s;
  }
  return where;
}

Stray worstStray(const SharedBoundary& boundary, int a, const Piece& piece, double edgeLength) {
  const BoundaryArc& arc = boundary.arcs[a];
  const size_t keys = boundary.keys.size();
  double longest = 0;
  for (size_t k = 0; k < keys; ++k)
    longest = std::max(longest, (piece.to[k] - piece.from[k]) * boundary.arcLength(static_cast<int>(k), a));
  const int n = std::max(1, static_cast<int>(std::ceil(longest / edgeLength - 1e-9)));
  Stray worst;
  for (size_t k = 0; k < keys; ++k) {
    const KeyBoundary& kb = boundary.keys[k];
    const ArcLengthLoop& loop = kb.loops[arc.loop];
    const double start = kb.arcStarts[arc.loop][arc.indexInLoop], length = boundary.arcLength(static_cast<int>(k), a);
    const double f0 = piece.from[k], f1 = piece.to[k];
    if (!(f1 > f0)) continue;
    for (int i = 0; i < n; ++i) {
      const double s0 = start + (f0 + (f1 - f0) * i / n) * length, s1 = start + (f0 + (f1 - f0) * (i + 1) / n) * length;
      const double d = loop.chordDeviation(s0, s1);
      if (d > worst.distance) worst = {d, ((farthestFromChord(loop, s0, s1) - start) / length - f0) / (f1 - f0)};
    }
  }
  return worst;
}

// The same piece along a cut's other side, which walks the other way.
Piece mirrored(const Piece& piece) {
  Piece out{piece.to, piece.from};
  for (double& f : out.from) f = 1 - f;
  for (double& f : out.to) f = 1 - f;
  return out;
}

// The knots (in every key) that splitting `piece` until it follows every key's outline within
// the chord tolerance adds, in order. Each split is where the piece strays most, in the key it
// strays most in (as Douglas-Peucker simplification picks its points), at the same fraction of
// the piece in the other keys: a rounded tip gets a knot at its apex and its flanks stay long.
// A piece is not split where either part would be shorter than `shortest` px in some key.
void split(const SharedBoundary& boundary, int a, const Piece& piece, const SharedBoundaryOptions& options,
           double shortest, int depth, std::vector<std::vector<double>>& out) {
  const int partner = boundary.arcs[a].partner;
  Stray worst = worstStray(boundary, a, piece, options.edgeLength);
  if (partner >= 0) {
    const Stray other = worstStray(boundary, partner, mirrored(piece), options.edgeLength);
    if (other.distance > worst.distance) worst = {other.distance, 1 - other.at};
  }
  if (depth > 24 || !(worst.distance > options.chordTolerance)) return;
  const size_t keys = boundary.keys.size();
  double t = std::clamp(worst.at, 0.05, 0.95);
  for (size_t k = 0; k < keys; ++k) {  // keep both parts at least `shortest` long, or do not split
    const double length = (piece.to[k] - piece.from[k]) * boundary.arcLength(static_cast<int>(k), a);
    if (length < 2 * shortest) return;
    t = std::clamp(t, shortest / length, 1 - shortest / length);
  }
  std::vector<double> middle(keys);
  for (size_t k = 0; k < keys; ++k) middle[k] = piece.from[k] + t * (piece.to[k] - piece.from[k]);
  split(boundary, a, {piece.from, middle}, options, shortest, depth + 1, out);
  out.push_back(middle);
  split(boundary, a, {middle, piece.to}, options, shortest, depth + 1, out);
}


}  // namespace

// Knots where the arcs curve: each stretch between knots whose even chords would stray more than
// the chord tolerance from some key's outline is split (in every key) until they do not. A cut's
// two sides get the same knots, mirrored, so that they stay copies of each other.
void placeCurveKnots(SharedBoundary& boundary, const SharedBoundaryOptions& options) {
  const size_t keys = boundary.keys.size();
  const double shortest = std::min(0.5, options.edgeLength / 4);  // px
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    BoundaryArc& arc = boundary.arcs[a];
    if (arc.partner >= 0 && arc.partner < static_cast<int>(a)) continue;  // done with its partner
    const size_t knots = arc.knotCornerIn.size();
    std::vector<std::vector<double>> fractions;  // [knot][key], the new list
    std::vector<std::vector<char>> cornerIn;
    for (size_t j = 0; j <= knots; ++j) {
      Piece piece{std::vector<double>(keys), std::vector<double>(keys)};
      for (size_t k = 0; k < keys; ++k) {
        const std::vector<double>& f = boundary.keys[k].knotFractions[a];
        piece.from[k] = j > 0 ? f[j - 1] : 0;
        piece.to[k] = j < knots ? f[j] : 1;
      }
      std::vector<std::vector<double>> added;
      split(boundary, static_cast<int>(a), piece, options, shortest, 0, added);
      for (std::vector<double>& m : added) {
        fractions.push_back(std::move(m));
        cornerIn.emplace_back(keys, 0);
      }
      if (j < knots) {
        fractions.push_back(piece.to);
        cornerIn.push_back(arc.knotCornerIn[j]);
      }
    }
    if (arc.partner >= 0) {  // cut sides have no corner knots: these are all new, mirrored there
      BoundaryArc& side = boundary.arcs[arc.partner];
      side.knotCornerIn = cornerIn;
      for (size_t k = 0; k < keys; ++k) {
        std::vector<double>& f = boundary.keys[k].knotFractions[arc.partner];
        f.clear();
        for (auto knot = fractions.rbegin(); knot != fractions.rend(); ++knot) f.push_back(1 - (*knot)[k]);
      }
    }
    arc.knotCornerIn = std::move(cornerIn);
    for (size_t k = 0; k < keys; ++k) {
      std::vector<double>& f = boundary.keys[k].knotFractions[a];
      f.clear();
      for (const std::vector<double>& knot : fractions) f.push_back(knot[k]);
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
    const int partner = boundary.arcs[a].partner;  // cut sides: mirrored knots, piece j there is piece n - 1 - j
    if (partner < 0) continue;
    std::vector<int>& mine = pieces[a];
    std::vector<int>& theirs = pieces[partner];
    for (size_t j = 0; j < mine.size() && j < theirs.size(); ++j) {
      int& other = theirs[theirs.size() - 1 - j];
      mine[j] = other = std::max(mine[j], other);
    }
  }
  for (const std::vector<int>& loop : boundary.loopArcs) {
    int sum = 0;
    for (int a : loop) sum += total(a);
    for (size_t i = 0; sum < 3; ++i, ++sum) {
      const int a = loop[i % loop.size()];
      ++pieces[a].back();
      if (boundary.arcs[a].partner >= 0) pieces[boundary.arcs[a].partner].front() = pieces[a].back();  // mirrored
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
