// Every key's drawing as the GPU samples it (renderers/artwork_texture.h), made on the CPU so that
// a player can prepare it off its window's thread: premultiplied alpha, one layer per key of the
// largest drawing's size (a smaller drawing in its layer's top-left corner, transparent padding),
// and a full mip chain, each level made from the one above as vkCmdBlitImage with VK_FILTER_LINEAR
// makes it (bilinear at the smaller level's texel centres, clamped to the edge; an exact 2 x 2
// average where a side halves evenly). The upload is then one copy per level.
#pragma once

#include "core/png_image.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ib::render {

struct TextureLevels {
  struct Level {
    int width = 0, height = 0;  // px
    size_t offset = 0;          // bytes into texels of its layer 0; layer l at offset + l * width * height * 4
  };
  int layers = 0;
  std::vector<Level> levels;    // [level]: level 0 is the largest drawing's size; the last is 1 x 1
  std::vector<uint8_t> texels;  // RGBA8, premultiplied, level-major, then layer, then rows top to bottom
};

// Throws std::invalid_argument for no drawings or an empty one.
TextureLevels textureLevels(const std::vector<RgbaImage>& drawings);

// Straight to premultiplied alpha, rounding: c * a / 255.
RgbaImage premultiplied(const RgbaImage& image);

}  // namespace ib::render
