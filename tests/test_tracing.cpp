#include "core/atomic_file.h"
#include "core/error.h"
#include "core/png_image.h"
#include "meshing/trace_cache.h"
#include "meshing/tracing.h"
#include "testkit/drawings.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <random>

using namespace ib;

namespace {

// Largest distance from the loop's vertices to the circle (centre, radius). A traced outline
// follows the pixel grid's rendering of the shape, so it can be off the true curve by up to
// about half a pixel plus potrace's smoothing: the tests allow 0.75 px.
double circleDeviation(const Polyline& loop, Eigen::Vector2d centre, double radius) {
  double worst = 0;
  for (const auto& p : loop) worst = std::max(worst, std::abs((p - centre).norm() - radius));
  return worst;
}

std::vector<Outline> trace(const RgbaImage& image, TracingOptions options = {}) {
  return traceOutlines(shapeMask(image, options), options, "drawing.png");
}

}  // namespace

TEST_CASE("png: an RGBA image survives a write and a read unchanged") {
  const RgbaImage image = test::drawShape(37, 21, test::disc(18, 10, 8), 200, 100, 50);
  const std::string path = test::scratchDirectory("png-roundtrip") + "/a.png";
  writePng(path, image);
  const RgbaImage back = readPng(path);
  CHECK(back.width == 37);
  CHECK(back.height == 21);
  CHECK(back.hasAlpha);
  CHECK(back.pixels == image.pixels);
}

TEST_CASE("png: missing, truncated and corrupt files are input errors naming the file") {
  const std::string dir = test::scratchDirectory("png-bad");
  CHECK_THROWS_WITH(readPng(dir + "/none.png"), Catch::Contains("none.png") && Catch::Contains("cannot open"));
  const std::string good = encodePng(test::drawShape(64, 64, test::disc(32, 32, 20)));
  writeFileAtomically(dir + "/truncated.png", good.substr(0, good.size() / 2));
  CHECK_THROWS_AS(readPng(dir + "/truncated.png"), InputError);
  CHECK_THROWS_WITH(readPng(dir + "/truncated.png"), Catch::Contains("truncated.png"));
  writeFileAtomically(dir + "/text.png", "this is not a picture");
  CHECK_THROWS_WITH(readPng(dir + "/text.png"), Catch::Contains("text.png") && Catch::Contains("not a readable PNG"));
  std::string flipped = good;
  for (size_t i = 60; i < flipped.size(); i += 7) flipped[i] = static_cast<char>(flipped[i] ^ 0x5a);
  writeFileAtomically(dir + "/flipped.png", flipped);
  CHECK_THROWS_AS(readPng(dir + "/flipped.png"), InputError);
}

TEST_CASE("tracing: a disc traces to one loop on its circle, within 0.75 px, with its area") {
  const auto outlines = trace(test::drawShape(128, 128, test::disc(64, 60, 40)));
  REQUIRE(outlines.size() == 1);
  CHECK(outlines[0].holes.empty());
  CHECK(loopArea(outlines[0].outer) == Approx(M_PI * 40 * 40).epsilon(0.01));
  CHECK(circleDeviation(outlines[0].outer, {64, 60}, 40) < 0.75);
}

TEST_CASE("tracing: a ring has one hole, oriented against its outer loop") {
  const auto outlines = trace(test::drawShape(128, 128, test::subtract(test::disc(64, 64, 50), test::disc(64, 64, 20))));
  REQUIRE(outlines.size() == 1);
  REQUIRE(outlines[0].holes.size() == 1);
  CHECK(loopArea(outlines[0].outer) == Approx(M_PI * 50 * 50).epsilon(0.01));
  CHECK(loopArea(outlines[0].holes[0]) == Approx(-M_PI * 20 * 20).epsilon(0.02));
  CHECK(circleDeviation(outlines[0].holes[0], {64, 64}, 20) < 0.75);
}

TEST_CASE("tracing: separate pieces and an island in a hole are components, specks are dropped") {
  const auto ring = test::subtract(test::disc(60, 60, 50), test::disc(60, 60, 30));
  const auto island = test::disc(60, 60, 12);
  const auto other = test::box(130, 20, 180, 60);
  const auto speck = test::box(150, 100, 152, 102);  // 4 px^2 < minArea 16
  const auto outlines = trace(test::drawShape(200, 128, test::unite(test::unite(ring, island), test::unite(other, speck))));
  REQUIRE(outlines.size() == 3);  // ring, box, island: largest first
  CHECK(outlines[0].holes.size() == 1);
  CHECK(loopArea(outlines[1].outer) == Approx(50 * 40).epsilon(0.01));
  CHECK(circleDeviation(outlines[2].outer, {60, 60}, 12) < 0.75);
}

TEST_CASE("tracing: an opaque drawing on paper and a palette PNG trace like the alpha drawing") {
  const auto shape = test::subtract(test::disc(64, 64, 45), test::box(50, 50, 78, 78));
  const double area = loopArea(trace(test::drawShape(128, 128, shape))[0].outer);
  TracingOptions enclosed;  // the square enclosed by the disc: a hole only when asked (test_paper.cpp)
  enclosed.holes = PaperHoles::kEnclosedPaper;
  const auto opaque = trace(test::drawOpaque(128, 128, shape), enclosed);
  REQUIRE(opaque.size() == 1);
  CHECK(opaque[0].holes.size() == 1);
  CHECK(loopArea(opaque[0].outer) == Approx(area).epsilon(0.01));
  const std::string path = test::scratchDirectory("palette") + "/palette.png";
  writeFileAtomically(path, test::palettePng(128, 128, shape));
  const RgbaImage palette = readPng(path);
  CHECK(palette.hasAlpha);
  const auto traced = trace(palette);
  REQUIRE(traced.size() == 1);
  CHECK(traced[0].holes.size() == 1);
  CHECK(loopArea(traced[0].outer) == Approx(area).epsilon(0.02));
}

TEST_CASE("tracing: a drawing with nothing on it is an input error naming it") {
  const RgbaImage empty = test::drawShape(32, 32, [](double, double) { return false; });
  CHECK_THROWS_AS(trace(empty), InputError);
  CHECK_THROWS_WITH(trace(empty), Catch::Contains("drawing.png") && Catch::Contains("empty drawing"));
}

namespace {

// Whether segments ab and cd cross at a point inside both.
bool segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Pairs of crossing segments among all loops (a loop against itself and the others).
int loopCrossings(const std::vector<Polyline>& loops) {
  int count = 0;
  for (size_t p = 0; p < loops.size(); ++p)
    for (size_t q = p; q < loops.size(); ++q) {
      const Polyline &A = loops[p], &B = loops[q];
      for (size_t i = 0; i < A.size(); ++i)
        for (size_t j = p == q ? i + 2 : 0; j < B.size(); ++j) {
          if (p == q && i == 0 && j + 1 == A.size()) continue;  // the closing segment meets the first
          count += segmentsCross(A[i], A[(i + 1) % A.size()], B[j], B[(j + 1) % B.size()]);
        }
    }
  return count;
}

}  // namespace

TEST_CASE("tracing: outlines moved onto the antialiased edge stay simple, also at tips on the image's border") {
  // 300 random 64 px blobs (sums of Gaussians, soft or hard edged, often cut by the border): the
  // move onto the edge swapped neighbouring points at sharp tips on the border in 3 of them.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0, 1);
  int traced = 0;
  for (int t = 0; t < 300; ++t) {
    std::vector<std::array<double, 3>> blobs(8);
    for (auto& b : blobs) b = {uniform(rng) * 64, uniform(rng) * 64, 2 + uniform(rng) * 6};
    RgbaImage image;
    image.hasAlpha = true;
    image.width = image.height = 64;
    image.pixels.assign(64 * 64 * 4, 0);
    const bool hard = t % 3 == 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        double field = 0;
        for (const auto& b : blobs) {
          const double d = std::hypot(x + 0.5 - b[0], y + 0.5 - b[1]);
          field += std::exp(-d * d / (2 * b[2] * b[2]));
        }
        const double a = std::clamp((field - 0.5) * 4 + 0.5, 0.0, 1.0);
        image.at(x, y)[3] = static_cast<uint8_t>(std::lround(255 * (hard ? (a >= 0.5 ? 1.0 : 0.0) : a)));
      }
    TracingOptions options;
    options.minArea = 4;
    std::vector<Outline> outlines;
    try {
      outlines = traceOutlines(shapeMask(image, options, {}, "blob"), options, "blob");
    } catch (const InputError&) {
      continue;  // nothing of 4 px^2
    }
    std::vector<Polyline> loops;
    for (const Outline& o : outlines) {
      loops.push_back(o.outer);
      for (const Polyline& h : o.holes) loops.push_back(h);
    }
    INFO("image " << t << (hard ? " (hard edged)" : ""));
    CHECK(loopCrossings(loops) == 0);
    ++traced;
  }
  CHECK(traced > 250);
}

TEST_CASE("trace cache: a drawing is traced once while its file, the options and the hole points are unchanged, and "
          "again when one changes") {
  const std::string dir = test::scratchDirectory("trace-cache");
  const std::string file = dir + "/disc.png";
  writePng(file, test::drawShape(128, 128, test::disc(64, 60, 40)));
  TraceCache cache;
  const std::vector<Outline> first = cache.traced(file, {}, {}).outlines;
  CHECK(cache.traced(file, {}, {}).outlines.size() == first.size());
  CHECK(cache.hits() == 1);
  CHECK(cache.traced(file, {}, {}).size == std::array<int, 2>{128, 128});
  CHECK(cache.hits() == 2);
  TracingOptions other;
  other.alphaThreshold = 64;
  cache.traced(file, other, {});  // other options: traced again
  CHECK(cache.hits() == 2);
  // Another drawing under the same name (a larger disc, a later time): traced again, and it is the new one.
  writePng(file, test::drawShape(128, 128, test::disc(64, 60, 50)));
  std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) + std::chrono::seconds(2));
  const std::vector<Outline> redrawn = cache.traced(file, {}, {}).outlines;
  CHECK(cache.hits() == 2);
  REQUIRE(redrawn.size() == 1);
  CHECK(loopArea(redrawn[0].outer) == Approx(M_PI * 50 * 50).epsilon(0.01));
}
