// Sprites drawn in code for the edge-length and sampling tests (test_mesh_size.cpp,
// test_scene_options_cli.cpp): a coloured bird with thin parts (a beak, legs and toes) at any
// size, antialiased like exported artwork; and a 16 x 16 pixel-art slime, hard-edged with a
// 4-colour palette.
#pragma once

#include "core/png_image.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace test {

namespace sprite_detail {

inline bool inTriangle(double x, double y, double ax, double ay, double bx, double by, double cx, double cy) {
  const double d1 = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
  const double d2 = (cx - bx) * (y - by) - (cy - by) * (x - bx);
  const double d3 = (ax - cx) * (y - cy) - (ay - cy) * (x - cx);
  return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
}

// The bird in its 64-unit design: 0 outside, 1 body or head, 2 beak, 3 legs and toes, 4 eye.
inline int birdPart(double x, double y) {
  const auto disc = [&](double cx, double cy, double r) { return (x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r; };
  const auto box = [&](double x0, double y0, double x1, double y1) { return x >= x0 && x <= x1 && y >= y0 && y <= y1; };
  if (disc(47, 18, 1.6)) return 4;
  if (inTriangle(x, y, 51, 17, 63, 19.5, 51, 22)) return 2;  // beak: 12 units long, 5 at its base
  const double ex = (x - 30) / 17, ey = (y - 33) / 11;
  if (ex * ex + ey * ey < 1 || disc(45, 20, 8) || inTriangle(x, y, 14, 30, 3, 22, 15, 35)) return 1;  // body, head, tail
  if (box(25.2, 42, 26.8, 55.8) || box(35.2, 42, 36.8, 55.8) || box(19, 54.2, 30, 55.8) || box(32, 54.2, 42, 55.8)) return 3;
  return 0;
}

}  // namespace sprite_detail

// The bird at size x size px, rotated by `leanDegrees` about its feet (a second key), 4 x 4
// samples per pixel: alpha is coverage, colour the mean of the covered samples' colours.
inline ib::RgbaImage birdSprite(int size, double leanDegrees = 0) {
  static const std::array<std::array<int, 3>, 5> colours = {{{0, 0, 0}, {59, 143, 217}, {240, 176, 32}, {224, 138, 30}, {17, 17, 17}}};
  ib::RgbaImage image;
  image.width = image.height = size;
  image.hasAlpha = true;
  image.pixels.assign(static_cast<size_t>(size) * size * 4, 0);
  const double scale = 64.0 / size, c = std::cos(leanDegrees * M_PI / 180), s = std::sin(leanDegrees * M_PI / 180);
  for (int py = 0; py < size; ++py)
    for (int px = 0; px < size; ++px) {
      int covered = 0, sum[3] = {0, 0, 0};
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const double x = (px + (i + 0.5) / 4) * scale - 30, y = (py + (j + 0.5) / 4) * scale - 56;  // about the feet
          const int part = sprite_detail::birdPart(30 + c * x + s * y, 56 - s * x + c * y);
          if (part == 0) continue;
          ++covered;
          for (int k = 0; k < 3; ++k) sum[k] += colours[part][k];
        }
      uint8_t* p = image.at(px, py);
      if (covered == 0) continue;
      for (int k = 0; k < 3; ++k) p[k] = static_cast<uint8_t>(sum[k] / covered);
      p[3] = static_cast<uint8_t>(covered * 255 / 16);
    }
  return image;
}

// The pixel-art slime, 16 x 16: tall, or squashed (the second key). Alpha 0 or 255 only.
inline ib::RgbaImage slimePixelArt(bool squashed) {
  static const std::vector<std::string> tall = {
      "................", "......gggg......", ".....gggggg.....", "....gggggggg....", "...gggggggggg...", "...gwwggggwwg...",
      "...gwkggggwkg...", "..gggggggggggg..", "..gggggggggggg..", "..ggggddddgggg..", "..gggggggggggg..", "..gggggggggggg..",
      "..dggggggggggd..", "...dddddddddd...", "................", "................"};
  static const std::vector<std::string> flat = {
      "................", "................", "................", "................", "................", "......gggg......",
      "....gggggggg....", "..gggggggggggg..", ".gggwwggggwwggg.", ".gggwkggggwkggg.", "gggggggggggggggg", "ggggggddddgggggg",
      "gggggggggggggggg", "dggggggggggggggd", ".dddddddddddddd.", "................"};
  const std::vector<std::string>& art = squashed ? flat : tall;
  ib::RgbaImage image;
  image.width = image.height = 16;
  image.hasAlpha = true;
  image.pixels.assign(16 * 16 * 4, 0);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const std::array<uint8_t, 4> c = art[y][x] == 'g'   ? std::array<uint8_t, 4>{60, 180, 75, 255}
                                       : art[y][x] == 'd' ? std::array<uint8_t, 4>{30, 110, 45, 255}
                                       : art[y][x] == 'w' ? std::array<uint8_t, 4>{255, 255, 255, 255}
                                       : art[y][x] == 'k' ? std::array<uint8_t, 4>{20, 20, 20, 255}
                                                          : std::array<uint8_t, 4>{0, 0, 0, 0};
      std::copy(c.begin(), c.end(), image.at(x, y));
    }
  return image;
}

// The slime's palette, opaque colours as 0xRRGGBB.
inline std::vector<uint32_t> slimePalette() { return {0x3cb44b, 0x1e6e2d, 0xffffff, 0x141414}; }

}  // namespace test
