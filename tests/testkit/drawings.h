// Drawings generated in code for the scene and tracing tests: shapes given by an inside test,
// rasterized with 4 x 4 supersampled coverage as alpha (like anti-aliased artwork).
#pragma once

#include "core/png_image.h"

#include <functional>
#include <string>

namespace test {

using Inside = std::function<bool(double x, double y)>;  // drawing pixels, y down

// Coverage of `inside` as alpha over an ink colour (RGB); transparent elsewhere.
ib::RgbaImage drawShape(int width, int height, const Inside& inside, int r = 20, int g = 20, int b = 20);

// The same shape, opaque: ink where inside, `paper` colour elsewhere (no alpha channel used).
ib::RgbaImage drawOpaque(int width, int height, const Inside& inside, int paper = 255);

Inside disc(double cx, double cy, double radius);
Inside box(double x0, double y0, double x1, double y1);
Inside unite(Inside a, Inside b);
Inside subtract(Inside a, Inside b);

// A palette PNG (colour type 3 with a tRNS chunk) of the shape: index 0 transparent, 1 ink.
std::string palettePng(int width, int height, const Inside& inside);

// A fresh scratch directory under the system temp folder, unique to this process.
std::string scratchDirectory(const std::string& name);

}  // namespace test
