// The ink of a drawing's outline where a cut meets it: the colour and width of the dark line an
// artist drew round the shape, so that an edge a cut opens can be drawn with the same line
// (issue 46, item 3). CPU only.
#pragma once

#include "core/png_image.h"

#include <Eigen/Core>
#include <array>

namespace ib::render {

struct OutlineInk {
  bool found = false;                     // the drawing has an outline line there
  std::array<float, 4> colour{0, 0, 0, 1};  // straight RGBA in [0, 1]: the line's mean colour
  double width = 0;                       // drawing px, across the line
};

// Marches from `at` (drawing px, on or near the outline) along `inward` (into the shape, any
// length) from 4 px outside to 24 px inside, in half-pixel steps, bilinear samples. The line is
// the run of opaque samples (alpha >= 1/2) from the first one whose luminance stays below the
// fill's (the median of the opaque samples 8 to 24 px in) by at least `contrast`; found when it is
// at least 1 px wide and the fill is at least 2 px deeper than it ends.
OutlineInk outlineInk(const RgbaImage& drawing, const Eigen::Vector2d& at, const Eigen::Vector2d& inward,
                      double contrast = 0.15);

// The direction into the shape at `at` (drawing px): up the drawing's alpha, its gradient summed
// over the pixels within `radius` px (so a 1 px antialiased edge and a blurry one alike give the
// outline's normal). Zero where the alpha is flat.
Eigen::Vector2d inwardNormal(const RgbaImage& drawing, const Eigen::Vector2d& at, double radius = 3);

}  // namespace ib::render
