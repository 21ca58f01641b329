// Drawings as textures for clients that filter straight alpha: the colour of every fully
// transparent texel is taken from its nearest drawn neighbours (alpha bleeding, as sprite packers
// do), so bilinear filtering and mipmaps along an outline blend towards the drawing's own colour,
// not towards the black or white a paint program leaves under alpha 0. Alpha is unchanged.
#pragma once

#include "core/png_image.h"

namespace ib::gltf {

// Grows colour into transparent texels one ring per pass, for `passes` rings (default 16, enough
// for the mip levels a client shows at a quarter of the drawing's size and larger); texels farther
// away take the mean colour of the drawn ones.
RgbaImage bleedColour(const RgbaImage& image, int passes = 16);

}  // namespace ib::gltf
