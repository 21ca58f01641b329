// How much an inbetween ghosts where the drawings did not change (issue: correspondence from the
// artwork): over the pixels where every key's drawing is the same, an inbetween should be that
// drawing; a map between keys that is not the identity there cross-fades two copies of the
// artwork a little apart, which shows as doubled edges and smears.
#pragma once

#include "core/png_image.h"
#include "meshing/artwork_agreement.h"

#include <vector>

namespace ib::render {

struct Ghosting {
  double mean = 0;   // mean over the mask of the largest premultiplied RGBA channel difference, in 0-255
  double share = 0;  // fraction of the mask's pixels whose largest channel difference exceeds the threshold
  int pixels = 0;    // the mask's pixels compared
};

// `frame` (an inbetween, at the drawings' scale, its pixel (x, y) over the drawings' pixel (x, y))
// against `drawing` (any key: they agree over the mask), channel by channel in premultiplied RGBA
// (so a pixel transparent in both is equal whatever its colour). `threshold` /255, default 48.
Ghosting ghosting(const RgbaImage& frame, const RgbaImage& drawing, const AgreementMask& mask, int threshold = 48);

// The pixels of `image` on an edge of the artwork inside its shape: whose right or lower neighbour
// differs by more than `threshold` /255 in a premultiplied RGBA channel, `margin` px or more (in x
// and in y) from the paper (alpha under 128), so that the silhouette and its ink line, whose length
// follows the shape, do not count. Detail cross-faded from two places (a stripe doubled) has more
// such edges than the keys it is blended from.
int edgePixels(const RgbaImage& image, int threshold = 48, int margin = 4);

}  // namespace ib::render
