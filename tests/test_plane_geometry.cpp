#include "core/plane_geometry.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace ib;

namespace {

// A star-like loop with very uneven segments (lengths from about 1e-3 to 100 px) and repeated
// points (zero-length segments), the cases a bucketed lookup could get wrong.
Polyline unevenLoop(std::mt19937& random) {
  std::uniform_real_distribution<double> radius(20, 100), exponent(-3, 0);
  Polyline loop;
  double angle = 0;
  while (angle < 2 * M_PI) {
    const double r = radius(random);
    loop.push_back({r * std::cos(angle), r * std::sin(angle)});
    if (random() % 7 == 0) loop.push_back(loop.back());
    angle += std::pow(10.0, exponent(random));
  }
  return loop;
}

// The point at arc length s by bisection over the cumulative lengths (the definition).
Eigen::Vector2d pointByBisection(const Polyline& loop, const std::vector<double>& cumulative, double s) {
  const double total = cumulative.back();
  s = std::fmod(s, total);
  if (s < 0) s += total;
  const size_t i = std::min<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), s) - cumulative.begin() - 1,
                                    loop.size() - 1);
  const double span = cumulative[i + 1] - cumulative[i];
  const double t = span > 0 ? (s - cumulative[i]) / span : 0.0;
  return (1 - t) * loop[i] + t * loop[(i + 1) % loop.size()];
}

// Largest distance to the chord of the loop's points strictly between arc lengths s0 < s1, over
// every lap (the definition, by brute force).
double deviationByScan(const ArcLengthLoop& loop, double s0, double s1) {
  const Eigen::Vector2d a = loop.at(s0), b = loop.at(s1);
  const double total = loop.length();
  double worst = 0;
  for (double lap = std::floor(s0 / total) - 1; lap * total <= s1; ++lap)
    for (size_t i = 0; i < loop.points().size(); ++i) {
      const double s = lap * total + loop.parameterOfPoint(static_cast<int>(i));
      if (s <= s0 || s >= s1) continue;
      const Eigen::Vector2d& p = loop.points()[i];
      worst = std::max(worst, (a + closestParameter(a, b, p) * (b - a) - p).norm());
    }
  return worst;
}

// The brute-force deviation, to rounding: the scan and the walk order their arithmetic differently.
Approx sameDeviation(double expected) { return Approx(expected).epsilon(1e-12).margin(1e-9); }

}  // namespace

TEST_CASE("arc-length loop: the bucketed lookup finds the same point as bisection, also at vertices and past a lap") {
  std::mt19937 random(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Polyline points = unevenLoop(random);
    const ArcLengthLoop loop(points);
    std::vector<double> cumulative;
    for (size_t i = 0; i <= points.size(); ++i)
      cumulative.push_back(i < points.size() ? loop.parameterOfPoint(static_cast<int>(i)) : loop.length());
    std::uniform_real_distribution<double> anywhere(-2 * loop.length(), 3 * loop.length());
    std::vector<double> queries;
    for (int k = 0; k < 500; ++k) queries.push_back(anywhere(random));
    for (double c : cumulative)
      for (double s : {c, std::nextafter(c, -1e300), std::nextafter(c, 1e300)}) queries.push_back(s);
    for (double s : queries) {
      const Eigen::Vector2d expected = pointByBisection(points, cumulative, s);
      INFO("trial " << trial << ", s = " << s);
      REQUIRE(loop.at(s).x() == expected.x());
      REQUIRE(loop.at(s).y() == expected.y());
    }
  }
}

TEST_CASE("arc-length loop: chord deviation is the largest distance of the points strictly between the ends") {
  std::mt19937 random(11);
  for (int trial = 0; trial < 20; ++trial) {
    const ArcLengthLoop loop(unevenLoop(random));
    std::uniform_real_distribution<double> start(-loop.length(), 2 * loop.length()), span(0, 0.3 * loop.length());
    for (int k = 0; k < 300; ++k) {
      const double s0 = k % 10 == 0 ? loop.parameterOfPoint(k % static_cast<int>(loop.points().size())) : start(random);
      const double s1 = s0 + span(random);
      INFO("trial " << trial << ", s0 = " << s0 << ", s1 = " << s1);
      REQUIRE(loop.chordDeviation(s0, s1) == sameDeviation(deviationByScan(loop, s0, s1)));
    }
  }
}

TEST_CASE("arc-length loop: a path's chord deviation is the largest of its chords' deviations") {
  std::mt19937 random(12);
  for (int trial = 0; trial < 20; ++trial) {
    const ArcLengthLoop loop(unevenLoop(random));
    std::uniform_real_distribution<double> start(-loop.length(), 2 * loop.length()), span(0, 0.6 * loop.length());
    for (int k = 0; k < 300; ++k) {
      const double s0 = start(random);
      // Every fifth path has a middle end that goes backwards (that chord counts 0) or repeats s0.
      const double s1 = k % 5 == 0 ? s0 - span(random) : k % 5 == 1 ? s0 : s0 + span(random);
      const double s2 = s1 + span(random);
      const double expected = std::max(s1 > s0 ? deviationByScan(loop, s0, s1) : 0.0, deviationByScan(loop, s1, s2));
      INFO("trial " << trial << ", s = " << s0 << ", " << s1 << ", " << s2);
      REQUIRE(loop.chordDeviation({s0, s1, s2}) == sameDeviation(expected));
    }
    // Paths over more than a whole lap, in two chords and in one.
    const double s0 = start(random), s1 = s0 + 0.7 * loop.length(), s2 = s0 + 1.5 * loop.length();
    REQUIRE(loop.chordDeviation({s0, s1, s2}) ==
            sameDeviation(std::max(deviationByScan(loop, s0, s1), deviationByScan(loop, s1, s2))));
    REQUIRE(loop.chordDeviation({s0, s2}) == sameDeviation(deviationByScan(loop, s0, s2)));
  }
}
