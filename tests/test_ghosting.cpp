// The ghost figure (output/ghosting.h): over the pixels where every key agrees, an inbetween equal
// to them has none, and one carrying the artwork a few pixels off has it.
#include "output/ghosting.h"

#include <catch2/catch.hpp>

using namespace ib;

namespace {

// A 64 x 64 drawing: an opaque orange square with a dark 4 px stripe at row `stripe`, on transparent paper.
RgbaImage drawing(int stripe, int shift = 0) {
  RgbaImage image;
  image.width = image.height = 64;
  image.pixels.assign(64 * 64 * 4, 0);
  for (int y = 10; y < 54; ++y)
    for (int x = 10 + shift; x < 54 + shift; ++x) {
      uint8_t* p = &image.pixels[4 * (static_cast<size_t>(y) * 64 + x)];
      const bool dark = y >= stripe && y < stripe + 4;
      p[0] = dark ? 60 : 240, p[1] = dark ? 40 : 150, p[2] = dark ? 30 : 50, p[3] = 255;
    }
  return image;
}

}  // namespace

TEST_CASE("ghosting: the keys agree everywhere but near what differs, and an inbetween equal to them has no ghost") {
  const std::vector<RgbaImage> keys{drawing(20), drawing(30)};  // the stripe moved 10 rows
  const AgreementMask mask = agreement(keys);
  CHECK(mask.count > 0);
  for (int x = 7; x < 57; ++x)
    for (int y = 17; y < 37; ++y) CHECK_FALSE(mask.inside[static_cast<size_t>(y) * 64 + x]);  // both stripes and 3 px round
  CHECK(mask.inside[static_cast<size_t>(45) * 64 + 30]);  // the square below them
  CHECK(mask.inside[static_cast<size_t>(5) * 64 + 5]);    // the paper
  const render::Ghosting g = render::ghosting(keys[1], keys[0], mask);
  CHECK(g.mean == 0);
  CHECK(g.share == 0);
  CHECK(g.pixels == mask.count);
}

TEST_CASE("ghosting: an inbetween carrying the artwork 3 px aside ghosts where its edges land") {
  const std::vector<RgbaImage> keys{drawing(20), drawing(20)};
  const AgreementMask mask = agreement(keys);
  const render::Ghosting g = render::ghosting(drawing(20, 3), keys[0], mask);
  CHECK(g.share > 0.05);
  CHECK(g.mean > 10);
  AgreementOptions drawn;
  drawn.opaqueOnly = true;
  CHECK(agreement(keys, drawn).count < mask.count);
}

TEST_CASE("ghosting: a stripe cross-faded from two places has twice the edges inside the shape; the silhouette counts none") {
  const RgbaImage one = drawing(20), other = drawing(30);
  // The stripe's top and bottom rows, from x = 14 to 49 (4 px in from the paper on either side).
  CHECK(render::edgePixels(one) == 2 * 36);
  // No detail: the square alone has its silhouette, 4 px from the paper, and nothing else.
  CHECK(render::edgePixels(drawing(100)) == 0);
  // The two keys blended half and half: two stripes at half strength, each with its two edges.
  RgbaImage blend = one;
  for (size_t i = 0; i < blend.pixels.size(); ++i) blend.pixels[i] = static_cast<uint8_t>((one.pixels[i] + other.pixels[i]) / 2);
  CHECK(render::edgePixels(blend) == 4 * 36);
}
