// A contact sheet: frames shrunk to tiles and laid out in rows on one picture, composited over a
// background colour so transparent frames stay visible.
#pragma once

#include "core/png_image.h"

#include <array>
#include <vector>

namespace ib::render {

struct ContactSheetOptions {
  int tileWidth = 240;                          // pixels; tiles keep the frames' aspect ratio
  int columns = 0;                              // 0: about square, ceil(sqrt(frames))
  int gap = 4;                                  // pixels between and around tiles
  std::array<uint8_t, 3> background{255, 255, 255};  // behind every tile and between them
};

// Shrinks a straight-alpha frame by box filtering (premultiplied, so edges stay clean) to
// width x height pixels (at most the frame's size).
RgbaImage shrink(const RgbaImage& frame, int width, int height);

// The sheet of `tiles` (each already shrunk to the same size, e.g. by shrink()), row by row. Opaque.
RgbaImage contactSheet(const std::vector<RgbaImage>& tiles, const ContactSheetOptions& options);

}  // namespace ib::render
