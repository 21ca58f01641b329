// Outlines matched by shape (meshing/outline_matching.h): where two outlines coincide their points
// correspond, a part that moved does not drag the rest, and the match never stops or runs away.
#include "meshing/outline_matching.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ib;

namespace {

using Points = std::vector<Eigen::Vector2d>;

// n points evenly spaced by arc length along the polyline `corners`.
Points evenly(const Points& corners, int n) {
  std::vector<double> at{0};
  for (size_t i = 1; i < corners.size(); ++i) at.push_back(at.back() + (corners[i] - corners[i - 1]).norm());
  Points out;
  for (int i = 0; i < n; ++i) {
    const double s = at.back() * i / (n - 1);
    size_t k = 1;
    while (k + 1 < corners.size() && at[k] < s) ++k;
    const double t = (s - at[k - 1]) / (at[k] - at[k - 1]);
    out.push_back(corners[k - 1] + t * (corners[k] - corners[k - 1]));
  }
  return out;
}

// Key sample position (fraction of n - 1) -> the key's point, interpolated.
Eigen::Vector2d pointAt(const Points& p, double fraction) {
  const double x = fraction * (p.size() - 1);
  const size_t i = std::min(static_cast<size_t>(x), p.size() - 2);
  return p[i] + (x - i) * (p[i + 1] - p[i]);
}

}  // namespace

TEST_CASE("outline matching: identical outlines match point for point") {
  const Points line = evenly({{0, 0}, {60, 0}, {60, 40}, {0, 70}}, 200);
  const std::vector<double> match = matchByShape(line, line);
  for (size_t i = 0; i < line.size(); ++i) CHECK((pointAt(line, match[i]) - line[i]).norm() < 1e-9);
}

TEST_CASE("outline matching: where a part moved, the part that did not matches itself within a pixel, where arc length "
          "is off by its length's change") {
  // The same 100 px base in both; then a tail up (reference) or a longer tail out to the right (key).
  const Points reference = evenly({{0, 0}, {100, 0}, {100, -40}}, 300);
  const Points key = evenly({{0, 0}, {100, 0}, {160, -20}}, 300);
  const std::vector<double> match = matchByShape(reference, key);
  double worstBase = 0, worstArcLength = 0;
  for (size_t i = 0; i < reference.size(); ++i) {
    if (reference[i].x() > 95) continue;  // the base, away from the bend
    worstBase = std::max(worstBase, (pointAt(key, match[i]) - reference[i]).norm());
    worstArcLength = std::max(worstArcLength, (key[i] - reference[i]).norm());
  }
  CHECK(worstBase < 1.0);
  CHECK(worstArcLength > 10);  // what the paper's arc length does here
}

TEST_CASE("outline matching: the match runs from end to end, increasing, between half and twice as fast as arc length") {
  const Points reference = evenly({{0, 0}, {50, 0}, {50, 50}, {100, 50}}, 150);
  const Points key = evenly({{0, 5}, {20, 60}, {100, 55}}, 150);
  const std::vector<double> match = matchByShape(reference, key);
  CHECK(match.front() == 0);
  CHECK(match.back() == 1);
  const double step = 1.0 / (reference.size() - 1);
  for (size_t i = 1; i < match.size(); ++i) {
    CHECK(match[i] > match[i - 1]);
    CHECK(match[i] - match[i - 1] <= 2 * step + 1e-12);
  }
}
