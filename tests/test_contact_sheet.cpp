#include "core/error.h"
#include "output/contact_sheet.h"
#include "render_fixtures.h"

#include <catch2/catch.hpp>

using namespace ib;
using namespace ib::render;

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
  CHECK_THROWS_AS(contactSheet({}, options), InputError);
}
