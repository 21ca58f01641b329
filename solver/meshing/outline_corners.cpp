#include "meshing/outline_corners.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ib {

namespace {

// Signed angle from direction at(s) - at(s - r) to at(s + r) - at(s), in (-pi, pi].
double turning(const ArcLengthLoop& loop, double s, double r) {
  const Eigen::Vector2d a = loop.at(s - r), b = loop.at(s), c = loop.at(s + r);
  const Eigen::Vector2d in = b - a, out = c - b;
  return std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));
}

// The outline point within r of arc length s farthest from the chord at(s - r) -> at(s + r): the
// tip of the corner, where a vertex clips least of it (the turning's peak can sit a pixel off a
// lopsided tip). s itself when no outline point lies in that stretch.
double tipNear(const ArcLengthLoop& loop, double s, double r) {
  const double length = loop.length();
  const Eigen::Vector2d a = loop.at(s - r), b = loop.at(s + r);
  double best = s, farthest = (loop.at(s) - (a + closestParameter(a, b, loop.at(s)) * (b - a))).norm();
  const Polyline& points = loop.points();
  for (size_t i = 0; i < points.size(); ++i) {
    double along = loop.parameterOfPoint(static_cast<int>(i)) - s;
    along -= length * std::round(along / length);
    if (std::abs(along) > r) continue;
    const double d = (points[i] - (a + closestParameter(a, b, points[i]) * (b - a))).norm();
    if (d > farthest) {
      farthest = d;
      best = s + along;
    }
  }
  return std::fmod(best + length, length);
}

}  // namespace

std::vector<OutlineCorner> outlineCorners(const ArcLengthLoop& loop, const OutlineCornerOptions& options) {
  std::vector<OutlineCorner> corners;
  const double length = loop.length(), w = options.window;
  if (!(w > 0) || length < 4 * w) return corners;
  const double step = std::min(0.25, w / 8);
  const int n = static_cast<int>(std::ceil(length / step));
  const int reach = std::max(1, static_cast<int>(std::round(w / step)));
  std::vector<double> wide(n), close(n);
  for (int i = 0; i < n; ++i) {
    wide[i] = turning(loop, i * step, w);
    close[i] = turning(loop, i * step, w / 3);
  }
  for (int i = 0; i < n; ++i) {
    const double t = std::abs(wide[i]);
    if (t < options.minimumTurn) continue;
    bool peak = true;  // the largest within one window; the first of equal ones
    for (int d = -reach; d <= reach && peak; ++d) {
      const double other = std::abs(wide[((i + d) % n + n) % n]);
      peak = d == 0 || other < t || (other == t && d > 0);
    }
    if (!peak) continue;
    int sharpest = i;  // where the close-up turning peaks, within a third of the window
    for (int d = -reach / 3; d <= reach / 3; ++d) {
      const int j = ((i + d) % n + n) % n;
      if (std::abs(close[j]) > std::abs(close[sharpest])) sharpest = j;
    }
    if (std::abs(close[sharpest]) < options.concentration * t || close[sharpest] * wide[i] <= 0) continue;
    corners.push_back({tipNear(loop, sharpest * step, w / 3), wide[i]});
  }
  std::sort(corners.begin(), corners.end(), [](const OutlineCorner& a, const OutlineCorner& b) { return a.s < b.s; });
  return corners;
}

}  // namespace ib

namespace ib {

namespace {

// For each corner of `a`, the index of its partner in `b`, or -1: the order-preserving pairing
// of same-signed corners with the least cost (Needleman-Wunsch).
// `length`: px, a's arc length, the unit of the places' distance.
std::vector<int> pairCorners(const std::vector<ArcCorner>& a, const std::vector<ArcCorner>& b, double length,
                             const CornerMatchOptions& options) {
  const size_t n = a.size(), m = b.size();
  const double inf = std::numeric_limits<double>::infinity(), skip = options.unpairedCost;
  const auto pairCost = [&](size_t i, size_t j) {
    if (a[i].turn * b[j].turn <= 0) return inf;
    const double apart = (a[i].place - b[j].place).norm();
    return std::abs(a[i].fraction - b[j].fraction) + 0.5 * std::abs(a[i].turn - b[j].turn) / M_PI +
           (std::isfinite(apart) && length > 0 ? apart / length : 0);
  };
  std::vector<std::vector<double>> cost(n + 1, std::vector<double>(m + 1, 0));
  for (size_t i = 0; i <= n; ++i)
    for (size_t j = 0; j <= m; ++j) {
      if (i == 0 || j == 0) {
        cost[i][j] = skip * static_cast<double>(i + j);
        continue;
      }
      cost[i][j] = std::min({cost[i - 1][j] + skip, cost[i][j - 1] + skip, cost[i - 1][j - 1] + pairCost(i - 1, j - 1)});
    }
  std::vector<int> partner(n, -1);
  for (size_t i = n, j = m; i > 0 && j > 0;) {
    if (cost[i][j] == cost[i - 1][j - 1] + pairCost(i - 1, j - 1)) {
      partner[i - 1] = static_cast<int>(j - 1);
      --i, --j;
    } else if (cost[i][j] == cost[i - 1][j] + skip) {
      --i;
    } else {
      --j;
    }
  }
  return partner;
}

// Fraction in key `to` of the point at fraction f of key `from`, linear between knots (with the
// arc's ends as knots 0 and 1).
double carry(const std::vector<CornerKnot>& knots, int from, int to, double f) {
  double f0 = 0, g0 = 0;
  for (const CornerKnot& knot : knots) {
    const double a = knot.fractions[from], b = knot.fractions[to];
    if (f <= a) {
      const double t = a > f0 ? (f - f0) / (a - f0) : 0;
      return g0 + t * (b - g0);
    }
    f0 = a, g0 = b;
  }
  const double t = f0 < 1 ? (f - f0) / (1 - f0) : 0;
  return g0 + t * (1 - g0);
}

// Whether a knot at `fractions` keeps at least `gap` px [key] from the arc's ends and every knot.
bool spaced(const std::vector<CornerKnot>& knots, const std::vector<double>& fractions,
            const std::vector<double>& gap) {
  for (size_t k = 0; k < fractions.size(); ++k) {
    if (fractions[k] < gap[k] || fractions[k] > 1 - gap[k]) return false;
    for (const CornerKnot& knot : knots)
      if (std::abs(knot.fractions[k] - fractions[k]) < gap[k]) return false;
  }
  return true;
}

}  // namespace

std::vector<CornerKnot> cornerKnots(const std::vector<std::vector<ArcCorner>>& corners,
                                             const std::vector<double>& lengths, int reference,
                                             const CornerMatchOptions& options) {
  const int keys = static_cast<int>(corners.size());
  std::vector<double> gap(keys);
  for (int k = 0; k < keys; ++k) gap[k] = lengths[k] > 0 ? options.minimumGap / lengths[k] : 1;
  const std::vector<ArcCorner>& ref = corners[reference];
  std::vector<std::vector<int>> partner(keys);  // [key][reference corner]
  for (int k = 0; k < keys; ++k) {
    if (k == reference) continue;
    partner[k] = pairCorners(ref, corners[k], lengths[reference], options);
  }
  std::vector<CornerKnot> knots;
  std::vector<std::vector<char>> used(keys);
  for (int k = 0; k < keys; ++k) used[k].assign(corners[k].size(), 0);
  for (size_t i = 0; i < ref.size(); ++i) {
    std::vector<double> fractions(keys);
    bool everywhere = true;
    for (int k = 0; k < keys && everywhere; ++k) {
      const int j = k == reference ? static_cast<int>(i) : partner[k][i];
      everywhere = j >= 0;
      if (everywhere) fractions[k] = corners[k][j].fraction;
    }
    if (!everywhere || !spaced(knots, fractions, gap)) continue;
    knots.push_back({fractions, std::vector<char>(keys, 1)});
    used[reference][i] = 1;
    for (int k = 0; k < keys; ++k)
      if (k != reference) used[k][partner[k][i]] = 1;
  }
  // Every other corner: a knot already within `merge` px of it in its key becomes a corner there
  // too (a corner that appears over several keys is one knot); otherwise a knot of its own.
  const std::vector<CornerKnot> paired = knots;
  for (int k = 0; k < keys && options.unpaired; ++k)
    for (size_t j = 0; j < corners[k].size(); ++j) {
      if (used[k][j]) continue;
      const double f = corners[k][j].fraction, merge = lengths[k] > 0 ? options.mergeDistance / lengths[k] : 1;
      size_t near = knots.size();
      for (size_t i = 0; i < knots.size(); ++i)
        if (std::abs(knots[i].fractions[k] - f) < merge &&
            (near == knots.size() || std::abs(knots[i].fractions[k] - f) < std::abs(knots[near].fractions[k] - f)))
          near = i;
      if (near < knots.size()) {
        CornerKnot& knot = knots[near];
        const double before = near > 0 ? knots[near - 1].fractions[k] : 0;
        const double after = near + 1 < knots.size() ? knots[near + 1].fractions[k] : 1;
        if (!knot.corner[k] && f - before >= gap[k] && after - f >= gap[k]) {
          knot.fractions[k] = f;
          knot.corner[k] = 1;
        }
        continue;
      }
      std::vector<double> fractions(keys);
      for (int o = 0; o < keys; ++o) fractions[o] = carry(paired, k, o, f);
      if (!spaced(knots, fractions, gap)) continue;
      CornerKnot knot{fractions, std::vector<char>(keys, 0)};
      knot.corner[k] = 1;
      knots.insert(std::upper_bound(knots.begin(), knots.end(), knot,
                                    [k](const CornerKnot& a, const CornerKnot& b) { return a.fractions[k] < b.fractions[k]; }),
                   knot);
    }
  return knots;
}

}  // namespace ib
