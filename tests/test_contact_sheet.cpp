#include "core/error.h"
#include "output/contact_sheet.h"
#include "render_fixtures.h"

#include <catch2/catch.hpp>
#include <stdexcept>

#include <algorithm>
#include <cmath>

using namespace ib;
using namespace ib::render;

namespace {

// A deterministic scramble of (x, y, channel) to 0..255.
uint8_t noise(int x, int y, int channel) {
  unsigned h = static_cast<unsigned>(x) * 73856093u ^ static_cast<unsigned>(y) * 19349663u ^
               static_cast<unsigned>(channel) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return static_cast<uint8_t>(h & 255u);
}

// Premultiplied RGBA (colour times alpha / 255, then alpha) in [0, 255] of output pixel (x, y) of
// `frame` shrunk to width x height, by brute force: every source pixel weighted by the area of its
// overlap with the pixel's footprint [x, x + 1) * frame.width / width (and likewise in y).
std::array<double, 4> exactAreaAverage(const RgbaImage& frame, int width, int height, int x, int y) {
  const double sx = double(frame.width) / width, sy = double(frame.height) / height;  // source px per output px
  std::array<double, 4> sum{0, 0, 0, 0};
  for (int j = 0; j < frame.height; ++j) {
    const double dy = std::min(j + 1.0, (y + 1) * sy) - std::max(double(j), y * sy);
    if (dy <= 0) continue;
    for (int i = 0; i < frame.width; ++i) {
      const double dx = std::min(i + 1.0, (x + 1) * sx) - std::max(double(i), x * sx);
      if (dx <= 0) continue;
      const uint8_t* p = frame.at(i, j);
      for (int c = 0; c < 3; ++c) sum[c] += dx * dy * p[c] * p[3] / 255.0;
      sum[3] += dx * dy * p[3];
    }
  }
  for (double& v : sum) v /= sx * sy;
  return sum;
}

std::array<double, 4> premultiplied(const RgbaImage& image, int x, int y) {
  const std::array<double, 4> p = test::pixel(image, x, y);
  return {p[0] * p[3] / 255, p[1] * p[3] / 255, p[2] * p[3] / 255, p[3]};
}

// Straight-alpha noise, a tenth of it fully transparent (with a colour that must not show).
RgbaImage noiseImage(int width, int height) {
  return test::paintedImage(width, height, [](int x, int y) {
    const uint8_t a = noise(x, y, 3) < 26 ? 0 : noise(x, y, 3);
    return std::array<uint8_t, 4>{noise(x, y, 0), noise(x, y, 1), noise(x, y, 2), a};
  });
}

// The integral of clamp(u, 0, 1) from 0 to u.
double clampIntegral(double u) { return u < 0 ? 0 : u < 1 ? u * u / 2 : u - 0.5; }

// Opaque dark grey left of the line x = 100 + 0.3 y (source px), transparent right of it, each
// pixel's alpha the exact area of it inside, as an antialiased outline's is; with `transposed`,
// the same edge mirrored across the diagonal (a shallow edge, y = 100 + 0.3 x).
RgbaImage slantedEdge(int size, bool transposed) {
  return test::paintedImage(size, size, [transposed](int x, int y) {
    const int along = transposed ? x : y, across = transposed ? y : x;
    // Over the pixel's rows t in [along, along + 1), its covered width is clamp(100 + 0.3 t - across, 0, 1).
    const double start = 100 + 0.3 * along - across;
    const double coverage = (clampIntegral(start + 0.3) - clampIntegral(start)) / 0.3;
    return std::array<uint8_t, 4>{40, 40, 40, static_cast<uint8_t>(std::lround(255 * coverage))};
  });
}

}  // namespace

TEST_CASE("contact sheet: shrinking by a non-integer factor is the exact area average") {
  // Premultiplied 8-bit levels: the result's alpha is rounded once (0.5), its colour once more
  // before the alpha multiplies it back (another 0.5).
  const double alphaTolerance = 0.51, colourTolerance = 1.01;
  struct Case {
    int width, height, toWidth, toHeight;
  };
  for (const Case& c : {Case{384, 384, 240, 240}, Case{203, 117, 64, 37}, Case{100, 90, 99, 31}}) {
    const RgbaImage frame = noiseImage(c.width, c.height);
    const RgbaImage small = shrink(frame, c.toWidth, c.toHeight);
    REQUIRE(small.width == c.toWidth);
    REQUIRE(small.height == c.toHeight);
    double worstAlpha = 0, worstColour = 0;
    for (int y = 0; y < c.toHeight; ++y)
      for (int x = 0; x < c.toWidth; ++x) {
        const std::array<double, 4> got = premultiplied(small, x, y);
        const std::array<double, 4> want = exactAreaAverage(frame, c.toWidth, c.toHeight, x, y);
        for (int k = 0; k < 3; ++k) worstColour = std::max(worstColour, std::abs(got[k] - want[k]));
        worstAlpha = std::max(worstAlpha, std::abs(got[3] - want[3]));
      }
    INFO(c.width << "x" << c.height << " -> " << c.toWidth << "x" << c.toHeight);
    CHECK(worstAlpha <= alphaTolerance);
    CHECK(worstColour <= colourTolerance);
  }
}

TEST_CASE("contact sheet: a slanted edge shrunk 384 -> 240 px stays straight, with no stair steps") {
  // The edge advances 0.3 source px per source row, so 0.3 output px per output row whatever the
  // ratio; the covered width of each output row (its alpha summed, in output px) must follow that
  // line. Even an exact area average strays from it: a footprint of 1.6 source rows weighs whole
  // pixel rows, whose mean row lies within 1/8 / 1.6 rows of the footprint's centre, so by up to
  // 0.3 * 0.125 / 1.6^2 = 0.0146 output px; 8-bit rounding adds at most 0.006 px (three partial
  // output pixels a row at 0.5 / 255 each, two partial source pixels a source row at 1 / 255 / 1.6).
  const double widthTolerance = 0.021;  // output px
  for (bool transposed : {false, true}) {
    const RgbaImage small = shrink(slantedEdge(384, transposed), 240, 240);
    const auto alpha = [&](int along, int across) {
      return transposed ? small.at(along, across)[3] : small.at(across, along)[3];
    };
    double worst = 0;
    bool monotone = true;
    for (int along = 0; along < 240; ++along) {
      double width = 0;
      for (int across = 0; across < 240; ++across) {
        width += alpha(along, across) / 255.0;
        if (across > 0 && alpha(along, across) > alpha(along, across - 1)) monotone = false;
        if (along > 0 && alpha(along, across) < alpha(along - 1, across)) monotone = false;
      }
      const double centre = (along + 0.5) * 1.6;  // of the row's footprint, source px
      worst = std::max(worst, std::abs(width - (100 + 0.3 * centre) / 1.6));
    }
    INFO((transposed ? "shallow edge" : "steep edge") << ": covered width off its line by up to " << worst << " px");
    CHECK(worst <= widthTolerance);
    CHECK(monotone);  // fading across the edge, filling in along it: never back
  }
}

TEST_CASE("contact sheet: shrinking keeps a constant image constant and premultiplied mass within 0.5%") {
  const RgbaImage flat =
      test::paintedImage(1920, 1080, [](int, int) { return std::array<uint8_t, 4>{37, 150, 220, 180}; });
  const RgbaImage small = shrink(flat, 240, 135);
  bool constant = true;
  for (size_t p = 0; p < small.pixels.size(); p += 4)
    constant = constant && small.pixels[p] == 37 && small.pixels[p + 1] == 150 && small.pixels[p + 2] == 220 &&
               small.pixels[p + 3] == 180;
  CHECK(constant);

  const RgbaImage frame = noiseImage(384, 384);
  const RgbaImage tile = shrink(frame, 240, 240);
  const double area = (384.0 / 240) * (384.0 / 240);  // source px per output px
  std::array<double, 4> before{0, 0, 0, 0}, after{0, 0, 0, 0};
  for (int y = 0; y < 384; ++y)
    for (int x = 0; x < 384; ++x)
      for (int c = 0; c < 4; ++c) before[c] += premultiplied(frame, x, y)[c];
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 240; ++x)
      for (int c = 0; c < 4; ++c) after[c] += area * premultiplied(tile, x, y)[c];
  for (int c = 0; c < 4; ++c) CHECK(after[c] == Approx(before[c]).epsilon(0.005));
}

TEST_CASE("contact sheet: shrinking averages premultiplied colour, so transparent pixels add no fringe") {
  // Left column opaque red, right column transparent white: a 2x1 box average is half-covered red.
  const RgbaImage frame = test::paintedImage(4, 2, [](int x, int) {
    return x % 2 == 0 ? std::array<uint8_t, 4>{200, 0, 0, 255} : std::array<uint8_t, 4>{255, 255, 255, 0};
  });
  const RgbaImage small = shrink(frame, 2, 1);
  REQUIRE(small.width == 2);
  REQUIRE(small.height == 1);
  for (int x = 0; x < 2; ++x) {
    const std::array<double, 4> p = test::pixel(small, x, 0);
    CHECK(p[0] == Approx(200).margin(1));
    CHECK(p[1] == Approx(0).margin(1));
    CHECK(p[3] == Approx(127.5).margin(1));
  }
}

TEST_CASE("contact sheet: tiles land row by row over the background with gaps") {
  std::vector<RgbaImage> tiles;
  for (int i = 0; i < 5; ++i)
    tiles.push_back(test::paintedImage(10, 6, [i](int, int) { return std::array<uint8_t, 4>{uint8_t(40 * i), 0, 0, 255}; }));
  ContactSheetOptions options;
  options.gap = 2;
  const RgbaImage sheet = contactSheet(tiles, options);  // ceil(sqrt(5)) = 3 columns, 2 rows
  CHECK(sheet.width == 3 * 10 + 4 * 2);
  CHECK(sheet.height == 2 * 6 + 3 * 2);
  for (int i = 0; i < 5; ++i) {
    const int x = 2 + (i % 3) * 12 + 5, y = 2 + (i / 3) * 8 + 3;
    CHECK(test::pixel(sheet, x, y)[0] == 40 * i);
  }
  CHECK(test::pixel(sheet, 0, 0)[0] == 255);                  // the white background in the gap
  CHECK(test::pixel(sheet, 2 + 2 * 12 + 5, 2 + 8 + 3)[0] == 255);  // the empty sixth cell
  CHECK_THROWS_AS(contactSheet({}, options), std::invalid_argument);
}
