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

// Shrinks a straight-alpha frame to width x height pixels (each clamped to [1, the frame's size]) by
// an area filter: every output pixel is the exact area-weighted average of the source pixels its
// footprint covers, fractional ones at its edges included, so a non-integer ratio (384 -> 240 px)
// leaves straight outlines straight. Averages premultiplied colour, so transparent pixels add no
// fringe. Throws std::invalid_argument for an empty frame (a caller's error).
RgbaImage shrink(const RgbaImage& frame, int width, int height);

// The sheet of `tiles` (each already shrunk to the same size, e.g. by shrink()), row by row. Opaque.
RgbaImage contactSheet(const std::vector<RgbaImage>& tiles, const ContactSheetOptions& options);

}  // namespace ib::render
