#include "meshing/outline_matching.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ib {

namespace {

// Unit tangents of an open polyline (central differences, one-sided at the ends).
std::vector<Eigen::Vector2d> tangents(const std::vector<Eigen::Vector2d>& p) {
  const size_t n = p.size();
  std::vector<Eigen::Vector2d> t(n, Eigen::Vector2d::UnitX());
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d d = p[std::min(i + 1, n - 1)] - p[i > 0 ? i - 1 : 0];
    if (d.norm() > 1e-12) t[i] = d.normalized();
  }
  return t;
}

}  // namespace

std::vector<double> matchByShape(const std::vector<Eigen::Vector2d>& reference, const std::vector<Eigen::Vector2d>& key,
                                 const OutlineMatchOptions& options) {
  const int n = static_cast<int>(reference.size());
  if (n < 2 || key.size() != reference.size()) throw std::invalid_argument("matchByShape: needs two polylines of the same count >= 2");
  const std::vector<Eigen::Vector2d> tr = tangents(reference), tk = tangents(key);
  const double scale2 = options.scale * options.scale;
  const auto cost = [&](int i, int j) {
    const double d2 = (reference[i] - key[j]).squaredNorm();
    const double position = d2 / (d2 + scale2);
    // Tangents count only between points near each other: far apart (a part that moved, or keys
    // that differ everywhere) every pairing costs about the same, and the step penalty keeps the
    // match to arc length.
    return position + (1 - position) * options.tangentWeight * 0.5 * (1 - tr[i].dot(tk[j]));
  };
  // D(i, j): the cheapest path from (0, 0) to (i, j); step 0 diagonal, 1 from (i - 1, j - 2)
  // through (i, j - 1), 2 from (i - 2, j - 1) through (i - 1, j).
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::vector<double> best(static_cast<size_t>(n) * n, kNone);
  std::vector<unsigned char> step(static_cast<size_t>(n) * n, 0);
  const auto at = [n](int i, int j) { return static_cast<size_t>(i) * n + j; };
  best[0] = cost(0, 0);
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) {
      // Cells that cannot reach (n - 1, n - 1) with slopes in [1/2, 2], or be reached from (0, 0), stay out.
      if (j > 2 * i || i > 2 * j || (n - 1 - j) > 2 * (n - 1 - i) || (n - 1 - i) > 2 * (n - 1 - j)) continue;
      double b = best[at(i - 1, j - 1)];
      unsigned char s = 0;
      if (j >= 2 && best[at(i - 1, j - 2)] < kNone) {
        const double c = best[at(i - 1, j - 2)] + cost(i, j - 1) + options.stepPenalty;
        if (c < b) b = c, s = 1;
      }
      if (i >= 2 && best[at(i - 2, j - 1)] < kNone) {
        const double c = best[at(i - 2, j - 1)] + cost(i - 1, j) + options.stepPenalty;
        if (c < b) b = c, s = 2;
      }
      if (b < kNone) {
        best[at(i, j)] = b + cost(i, j);
        step[at(i, j)] = s;
      }
    }
  // Back from (n - 1, n - 1) along the path's steps, a polyline in (i, j): every reference sample
  // gets the key position where the path crosses it (a (2, 1) step's middle sample, halfway).
  std::vector<double> out(n, 0);
  int i = n - 1, j = n - 1;
  while (i > 0) {
    out[i] = j;
    switch (step[at(i, j)]) {
      case 0: --i, --j; break;
      case 1: i -= 1, j -= 2; break;
      default: out[i - 1] = j - 0.5, i -= 2, j -= 1; break;
    }
  }
  for (double& f : out) f /= n - 1;
  return out;
}

void placeShapeKnots(SharedBoundary& boundary, int reference, const SharedBoundaryOptions& options) {
  const int keys = static_cast<int>(boundary.keys.size());
  const OutlineMatchOptions matching;
  const double knotSpacing = 2 * options.edgeLength;  // px of the reference's outline between new knots
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    BoundaryArc& arc = boundary.arcs[a];
    if (arc.partner >= 0) continue;  // cut sides stay copies of each other
    const size_t knots = arc.knotCornerIn.size();
    std::vector<std::vector<double>> fractions;  // [knot][key], the new list
    std::vector<std::vector<char>> cornerIn;
    for (size_t piece = 0; piece <= knots; ++piece) {
      std::vector<double> from(keys), to(keys);
      double longest = 0;
      for (int k = 0; k < keys; ++k) {
        const std::vector<double>& f = boundary.keys[k].knotFractions[a];
        from[k] = piece > 0 ? f[piece - 1] : 0;
        to[k] = piece < knots ? f[piece] : 1;
        longest = std::max(longest, (to[k] - from[k]) * boundary.arcLength(k, static_cast<int>(a)));
      }
      const double referenceLength = (to[reference] - from[reference]) * boundary.arcLength(reference, static_cast<int>(a));
      const int added = static_cast<int>(std::floor(referenceLength / knotSpacing)) - 1;  // new knots inside the piece
      if (added > 0) {
        const int n = std::clamp(static_cast<int>(std::ceil(longest / matching.spacing)) + 1, 8, matching.maxSamples);
        const auto sample = [&](int k) {
          std::vector<Eigen::Vector2d> p(n);
          for (int i = 0; i < n; ++i) p[i] = boundary.atFraction(k, static_cast<int>(a), from[k] + (to[k] - from[k]) * i / (n - 1));
          return p;
        };
        const std::vector<Eigen::Vector2d> ref = sample(reference);
        std::vector<std::vector<double>> matched(keys);  // [key][reference sample]: fraction of the piece
        for (int k = 0; k < keys; ++k)
          if (k != reference) matched[k] = matchByShape(ref, sample(k), matching);
        for (int m = 1; m <= added; ++m) {
          const double r = static_cast<double>(m) / (added + 1);  // along the reference's piece
          const double x = r * (n - 1);
          const int i = std::min(static_cast<int>(x), n - 2);
          std::vector<double> knot(keys);
          bool clear = true;  // of the places to keep knots away from
          for (int k = 0; k < keys; ++k) {
            const double along = k == reference ? r : matched[k][i] + (x - i) * (matched[k][i + 1] - matched[k][i]);
            knot[k] = from[k] + (to[k] - from[k]) * along;
            const Eigen::Vector2d p = boundary.atFraction(k, static_cast<int>(a), knot[k]);
            for (const Eigen::Vector2d& q : options.shapeKnotsClearOf) clear = clear && (p - q).norm() >= options.shapeKnotClearance;
          }
          if (!clear) continue;
          fractions.push_back(std::move(knot));
          cornerIn.emplace_back(keys, 0);
        }
      }
      if (piece < knots) {
        fractions.push_back(to);
        cornerIn.push_back(arc.knotCornerIn[piece]);
      }
    }
    arc.knotCornerIn = std::move(cornerIn);
    for (int k = 0; k < keys; ++k) {
      std::vector<double>& f = boundary.keys[k].knotFractions[a];
      f.clear();
      for (const std::vector<double>& knot : fractions) f.push_back(knot[k]);
    }
  }
}

namespace {

// Where p lies on key `key`'s outline: the arc (not a cut side) of the loop nearest to p and the
// fraction of that arc's length there; {-1, 0} when p lies on a cut side.
std::pair<int, double> arcFractionOf(const SharedBoundary& boundary, int key, const Eigen::Vector2d& p) {
  const KeyBoundary& kb = boundary.keys[key];
  LoopPoint best;
  size_t loop = 0;
  for (size_t l = 0; l < kb.loops.size(); ++l) {
    const LoopPoint q = nearestOnLoop(kb.loops[l].points(), p);
    if (q.distance < best.distance) best = q, loop = l;
  }
  if (kb.loops.empty()) return {-1, 0};
  const ArcLengthLoop& lp = kb.loops[loop];
  const double s = lp.parameterOf(best);
  for (int a : boundary.loopArcs[loop]) {
    const double along = std::fmod(s - kb.arcStarts[loop][boundary.arcs[a].indexInLoop] + 2 * lp.length(), lp.length());
    const double length = boundary.arcLength(key, a);
    if (along <= length) return {boundary.arcs[a].partner >= 0 ? -1 : a, length > 0 ? along / length : 0};
  }
  return {-1, 0};
}

}  // namespace

void placeArtworkKnots(SharedBoundary& boundary, const SharedBoundaryOptions& options) {
  const int keys = static_cast<int>(boundary.keys.size());
  for (const std::vector<Eigen::Vector2d>& points : options.artworkKnots) {
    if (static_cast<int>(points.size()) != keys) continue;
    bool nearFold = false;  // where a key folded before, the outline follows arc length
    for (const Eigen::Vector2d& p : points)
      for (const Eigen::Vector2d& q : options.shapeKnotsClearOf) nearFold = nearFold || (p - q).norm() < options.shapeKnotClearance;
    if (nearFold) continue;
    int arc = -2;
    std::vector<double> fractions(keys);
    for (int k = 0; k < keys && arc != -1; ++k) {
      const auto [a, f] = arcFractionOf(boundary, k, points[k]);
      arc = arc == -2 || arc == a ? a : -1;
      fractions[k] = f;
    }
    if (arc < 0) continue;
    // Its place among the arc's knots: the same in every key, an edge length clear of its neighbours.
    long index = -1;
    bool clear = true;
    for (int k = 0; k < keys && clear; ++k) {
      const std::vector<double>& f = boundary.keys[k].knotFractions[arc];
      const long i = std::lower_bound(f.begin(), f.end(), fractions[k]) - f.begin();
      const double before = i > 0 ? f[i - 1] : 0, after = i < static_cast<long>(f.size()) ? f[i] : 1;
      const double length = boundary.arcLength(k, arc);
      clear = (index < 0 || index == i) && (fractions[k] - before) * length >= options.edgeLength &&
              (after - fractions[k]) * length >= options.edgeLength;
      index = i;
    }
    if (!clear) continue;
    for (int k = 0; k < keys; ++k) {
      std::vector<double>& f = boundary.keys[k].knotFractions[arc];
      f.insert(f.begin() + index, fractions[k]);
    }
    auto& cornerIn = boundary.arcs[arc].knotCornerIn;
    cornerIn.insert(cornerIn.begin() + index, std::vector<char>(keys, 1));
  }
}

}  // namespace ib
