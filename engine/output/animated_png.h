// Animated PNG (APNG, https://wiki.mozilla.org/APNG_Specification): frames of one size played in
// a loop, shown by browsers and image viewers; viewers without APNG show the first frame. For the
// animated previews of `inbetween render --preview` and the gallery (docs/gallery.md).
#pragma once

#include "core/png_image.h"

#include <string>
#include <vector>

namespace ib::render {

// The file bytes of an APNG that shows `frames` (straight alpha, all the same size, at least one)
// for `frameMilliseconds` each, looping forever, each frame replacing the last. Throws
// std::invalid_argument for no frames or frames of different sizes (a caller's error).
std::string encodeAnimatedPng(const std::vector<RgbaImage>& frames, int frameMilliseconds);

}  // namespace ib::render
