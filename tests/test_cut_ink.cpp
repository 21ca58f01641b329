// The ink of a drawing's outline (engine/output/cut_ink.h), on discs drawn at the sizes artists
// use: a 32 px sprite with a 1 px line, 128 px with 3 px, 1024 px with 12 px, and a disc drawn
// without a line.
#include "output/cut_ink.h"
#include "render_fixtures.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>

using namespace ib;

namespace {

// A disc of radius r centred in a size x size picture: fill inside, a line of `line` px along its
// edge (none when 0), transparent outside; 4 x 4 samples a pixel, so its edge is antialiased.
RgbaImage inkedDisc(int size, double r, double line, std::array<uint8_t, 3> ink, std::array<uint8_t, 3> fill) {
  const double c = size / 2.0;
  return ib::test::paintedImage(size, size, [&](int x, int y) {
    double inside = 0, inked = 0;
    for (int sy = 0; sy < 4; ++sy)
      for (int sx = 0; sx < 4; ++sx) {
        const double d = std::hypot(x + (sx + 0.5) / 4 - c, y + (sy + 0.5) / 4 - c);
        if (d <= r) {
          inside += 1.0 / 16;
          if (d > r - line) inked += 1.0 / 16;
        }
      }
    std::array<uint8_t, 4> p{0, 0, 0, static_cast<uint8_t>(std::lround(255 * inside))};
    if (inside > 0)
      for (int k = 0; k < 3; ++k) p[k] = static_cast<uint8_t>(std::lround((inked * ink[k] + (inside - inked) * fill[k]) / inside));
    return p;
  });
}

}  // namespace

TEST_CASE("cut ink: the outline's colour and width are read where a cut meets it, at sprite and artwork sizes") {
  const std::array<uint8_t, 3> ink{32, 24, 48}, fill{230, 170, 60};
  struct Case {
    int size;
    double radius, line;
  };
  for (const Case& k : {Case{32, 14, 1}, Case{128, 56, 3}, Case{1024, 480, 12}}) {
    INFO(k.size << " px, line " << k.line << " px");
    const RgbaImage disc = inkedDisc(k.size, k.radius, k.line, ink, fill);
    const double c = k.size / 2.0;
    for (double angle : {0.0, 0.7, 2.0, 3.9}) {
      INFO("at " << angle << " rad");
      const Eigen::Vector2d normal(std::cos(angle), std::sin(angle));
      const render::OutlineInk found = render::outlineInk(disc, Eigen::Vector2d(c, c) + k.radius * normal, -normal);
      REQUIRE(found.found);
      CHECK(std::abs(found.width - k.line) <= 1.0);
      for (int ch = 0; ch < 3; ++ch) CHECK(std::abs(found.colour[ch] * 255 - ink[ch]) <= (k.line < 2 ? 48 : 16));
    }
  }
  // Without a line the fill starts at the edge: nothing to draw.
  const RgbaImage plain = inkedDisc(128, 56, 0, ink, fill);
  CHECK_FALSE(render::outlineInk(plain, Eigen::Vector2d(64 + 56, 64), Eigen::Vector2d(-1, 0)).found);
  // Nor where the march finds no shape at all.
  CHECK_FALSE(render::outlineInk(plain, Eigen::Vector2d(2, 2), Eigen::Vector2d(-1, 0)).found);
}

TEST_CASE("cut ink: the drawn test scenes' cuts meet an inked outline at both ends") {
  // tests/topology's drawings are inked (draw.py): a split drawn in the closed key runs from the
  // outline to the outline, so each end meets the line; it is read across the line, along the
  // outline's normal there (a cut may meet the outline at a slant).
  struct Cut {
    std::string drawing;
    Eigen::Vector2d from, to;
  };
  const std::string topology = std::string(INBETWEEN_ASSETS) + "/../tests/topology/";
  for (const Cut& cut : {Cut{"ring-open/o.png", {178, 128}, {218, 128}}, Cut{"drop-split/hang.png", {67.6, 140}, {188.4, 140}}}) {
    INFO(cut.drawing);
    const RgbaImage drawing = readPng(topology + cut.drawing);
    for (const Eigen::Vector2d& at : {cut.from, cut.to}) {
      const Eigen::Vector2d inward = render::inwardNormal(drawing, at);
      REQUIRE(inward.norm() > 0.5);
      const render::OutlineInk found = render::outlineInk(drawing, at, inward);
      INFO("at (" << at.transpose() << "): width " << found.width << ", colour " << found.colour[0] << " " << found.colour[1]
                  << " " << found.colour[2]);
      CHECK(found.found);
      CHECK(found.width >= 1.5);
      CHECK(found.width <= 5);  // draw.py's line is 3 px
      CHECK(found.colour[0] + found.colour[1] + found.colour[2] < 1.0);  // a dark line
    }
  }
}
