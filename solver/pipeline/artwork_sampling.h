// How the front ends (render, play, export) filter the key drawings' texels: the scene's
// `sampling` (docs/scene-format.md), where "auto", the default, means nearest for pixel art and
// linear for everything else. A command-line option overrides the scene.
#pragma once

#include "core/png_image.h"

#include <vector>

namespace ib {

struct Scene;  // scene/scene.h

// Pixel art: drawings with hard pixel edges and a small palette, which linear filtering would
// blur when magnified. True when every drawing has no partly transparent pixel (alpha 0 or 255
// everywhere: no antialiased edge) and their opaque pixels use at most kPixelArtColours distinct
// colours between them (what an 8-bit palette PNG can hold; antialiased line art, scans and
// photographs have thousands). False for no drawings.
constexpr int kPixelArtColours = 256;
bool isPixelArt(const std::vector<RgbaImage>& drawings);

// Whether to sample the drawings nearest-neighbour: scene.sampling kNearest, or kAuto and
// isPixelArt(drawings). `drawings` are the artwork the front end draws (pipeline/key_drawings.h:
// drawings on paper come with the paper made transparent and their antialiasing un-blended, so a
// scan has partly transparent rims and stays linear).
bool nearestSampling(const Scene& scene, const std::vector<RgbaImage>& drawings);

}  // namespace ib
