// Whether a key frame is its drawing (issue: faithful pixels, "keys are the drawings"): a frame
// rendered at w = e_i, at the drawing's size or an integer multiple of it, against the drawing
// as the same sampler magnifies it (nearest: each texel a square of scale x scale pixels; linear:
// bilinear between texel centres, clamped to the edge, in premultiplied alpha as the GPU filters).
// Compared in premultiplied RGBA, what shows over any background: a pixel transparent in both is
// equal whatever its colour.
#pragma once

#include "core/png_image.h"

namespace ib::render {

struct KeyFidelity {
  long long pixels = 0;     // pixels compared: the whole frame
  long long over = 0;       // pixels whose largest premultiplied channel difference exceeds the tolerance
  int worst = 0;            // the largest channel difference, 0-255
  int worstX = -1, worstY = -1;  // where (frame pixels), -1 when nothing differs
};

// The drawing magnified `scale` times (>= 1) as the renderer samples it, premultiplied.
// nearest: nearest texels; otherwise bilinear at each target pixel's centre.
RgbaImage magnifiedDrawing(const RgbaImage& drawing, int scale, bool nearest);

// `frame` (straight alpha, as written) against `drawing` (straight alpha) magnified `scale`
// times; pixels beyond either image count as transparent. `tolerance` in 0-255 (default 2).
// Throws std::invalid_argument for a scale under 1.
KeyFidelity keyFidelity(const RgbaImage& frame, const RgbaImage& drawing, int scale, bool nearest, int tolerance = 2);

}  // namespace ib::render
