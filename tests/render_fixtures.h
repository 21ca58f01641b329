// Scenes for the renderer and render-mesh tests: grid multimeshes in drawing pixels with synthetic
// artwork. CPU only; the Vulkan context they render with is in vulkan_fixtures.h.
#pragma once

#include "core/png_image.h"
#include "multimesh/multimesh.h"
#include "output/render_mesh.h"

#include <array>
#include <functional>
#include <vector>

namespace ib::test {

// An opaque or transparent drawing of width x height pixels, colour(x, y) per pixel.
RgbaImage paintedImage(int width, int height, const std::function<std::array<uint8_t, 4>(int x, int y)>& colour);

// A grid of nx x ny vertices covering [x0, x0 + side] x [y0, y0 + side] (drawing pixels) in every
// one of `keys` keys.
Multimesh squareGrid(int n, double x0, double y0, double side, int keys);

// A frame of positions x (kept by pointer) at weights w showing `view`, without overlays.
render::FrameDraw frameOf(const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, render::ViewBox view);

// Straight-alpha RGBA of pixel (x, y) as doubles in [0, 255].
std::array<double, 4> pixel(const RgbaImage& image, int x, int y);

// Sum of alpha / 255 over the image: the covered area in pixels.
double coveredArea(const RgbaImage& image);

// Two halves of a 32 x 32 drawing-pixel square, [8, 24] and [24, 40] along x and [0, 32] along y,
// with their own vertices along the cut x = 24. Key 0 draws the square whole (the cut glued,
// cohesive pairs along it); key 1 draws the right half 8 pixels further right (the cut open).
struct CutSquare {
  Multimesh mesh;
  std::vector<int> left, right;  // the vertices on the cut, bottom to top, of each half
};
CutSquare cutSquare();

// 48 x 32 drawings: key 0 opaque teal wherever the square is; key 1 opaque orange except the
// open cut x in [24, 32), which is transparent: sampled at the cut's sides, its texels blend
// with the transparent ones, as antialiased line art does along an outline.
std::vector<RgbaImage> cutSquareArtwork();

// x with the given vertices moved dx drawing pixels to the right.
Eigen::MatrixX2d shiftedRight(const Eigen::MatrixX2d& x, const std::vector<int>& vertices, double dx);

}  // namespace ib::test
