// Drawings on paper: for a drawing traced by colour (no alpha, or `tracing.background` given),
// which pixels are paper, found once and used both for tracing (the shape is everything that is
// not paper) and for the artwork (paper made transparent, its antialiased edge un-blended).
//
// Paper is the paper-coloured (or transparent) background 4-connected to the canvas border.
// Paper-coloured regions the drawing encloses (a white belly, the white of an eye) are part of
// the shape and stay opaque, unless the key marks them as holes (KeySpec::holes) or the scene
// asks for every enclosed paper region to be a hole (PaperHoles::kEnclosedPaper).
#pragma once

#include "core/png_image.h"
#include "meshing/tracing.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ib {

// True when the drawing is traced by its distance from the paper colour: it has no alpha, its
// alpha is opaque (>= options.alphaThreshold) everywhere, or options.background is set.
// Otherwise its alpha is the shape and it has no paper.
bool tracedByColour(const RgbaImage& image, const TracingOptions& options);

// Which pixels of a drawing are paper.
struct PaperMap {
  int width = 0, height = 0;
  std::array<int, 3> colour{255, 255, 255};  // the paper colour, RGB
  std::vector<uint8_t> paper;                // [y * width + x]: 1 paper (transparent), 0 shape
  bool at(int x, int y) const { return paper[static_cast<size_t>(y) * width + x] != 0; }
};

// The paper of a drawing traced by colour. A pixel is paper-coloured when its RGB distance from
// the paper colour is at most options.colorThreshold, or (with alpha) its alpha is under
// options.alphaThreshold. Paper: the paper-coloured pixels 4-connected to the border, to a
// transparent pixel, or to one of holePoints (drawing px); with PaperHoles::kEnclosedPaper every
// paper-coloured pixel. Throws InputError, label naming the drawing, when a hole point is off
// the canvas, on the drawing's ink, or in the paper round the drawing (transparent anyway).
PaperMap findPaper(const RgbaImage& image, const TracingOptions& options, const Polyline& holePoints,
                   const std::string& label);

// The artwork of a drawing on paper, straight alpha: paper transparent; ink pixels within 2 px
// of paper (and nearer to it than to enclosed paper, which they are a blend with) and paper
// pixels touching the shape un-blended from the paper colour
// (p = a ink + (1 - a) paper, with the ink colour taken from the nearest solid pixel of the
// shape that explains p, else GIMP's colour-to-alpha), so an antialiased outline becomes partly
// transparent ink; every other pixel of the shape (enclosed paper included) unchanged. With
// alpha, the result's alpha is the drawing's times the un-blended one.
RgbaImage paperToAlpha(const RgbaImage& image, const PaperMap& paper);

}  // namespace ib
