// Scenes for the renderer tests: grid multimeshes in drawing pixels with synthetic artwork, and a
// lavapipe context with the validation layer on.
#pragma once

#include "multimesh.h"
#include "png_image.h"
#include "render_mesh.h"
#include "vulkan_context.h"

#include <array>
#include <functional>

namespace ib::test {

// Headless lavapipe with VK_LAYER_KHRONOS_validation: tests require validationMessages() empty.
vk::VulkanContext validatedContext();

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

}  // namespace ib::test
