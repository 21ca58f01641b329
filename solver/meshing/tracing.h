// Drawings to outlines: a shape mask from a PNG (alpha, or everything that is not paper: meshing/paper.h),
// traced by potrace into smooth curves, flattened to polygons. Coordinates are drawing pixels
// (x right, y down, pixel (i, j) covering [i, i+1] x [j, j+1]).
#pragma once

#include "core/plane_geometry.h"
#include "core/png_image.h"
#include "scene/meshing_options.h"

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ib {

// One connected piece of a drawing: its outer loop (positive signed area) and its holes
// (negative signed area), each without repeated end point.
struct Outline {
  Polyline outer;
  std::vector<Polyline> holes;
};

// A pixel mask, row-major, true where the shape is. For a drawing traced by alpha, also its
// alpha (0..255, row-major) and the threshold, so that the traced curves can be brought onto the
// drawing's antialiased edge (traceOutlines); empty for one traced by colour.
struct ShapeMask {
  int width = 0, height = 0;
  std::vector<char> inside;
  std::vector<uint8_t> alpha;
  int threshold = 128;
  bool at(int x, int y) const { return inside[static_cast<size_t>(y) * width + x] != 0; }
};

// The shape: alpha >= alphaThreshold, or for a drawing traced by colour everything that is not
// paper (meshing/paper.h; holePoints mark enclosed paper regions that are holes, drawing px).
// label names the drawing in messages; throws InputError for a misplaced hole point, or for
// hole points on a drawing traced by alpha (its holes are its transparent pixels).
ShapeMask shapeMask(const RgbaImage& image, const TracingOptions& options, const Polyline& holePoints = {},
                    const std::string& label = "drawing");

// Traces the mask into components, largest first. With the mask's alpha, every traced point then
// moves along the outline's normal, by at most a pixel (the moves averaged over 2 px of outline),
// onto the drawing's edge: near partly transparent pixels where the alpha, interpolated
// bilinearly between pixel centres, crosses the threshold; elsewhere onto the boundary of the
// pixels inside. potrace's curves smooth the mask's pixel steps: they lie about 0.2 px inside a
// convex antialiased edge, a hard-edged rectangle's sides up to half a pixel in, a tip further.
// label names the drawing in messages. Throws InputError when nothing is left after dropping
// specks.
std::vector<Outline> traceOutlines(const ShapeMask& mask, const TracingOptions& options, const std::string& label);

// Signed area of a loop by the shoelace formula on the coordinates as given: positive when the
// loop turns counterclockwise with y up (which looks clockwise on screen, y down).
double loopArea(const Polyline& loop);

}  // namespace ib
