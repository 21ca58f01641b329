// An SVG picture of one key of a multimesh over its drawing, so an author sees what was built:
// triangles in thin blue, cohesive edges in red, features as labelled dots. The drawing is embedded
// (base64 PNG), so the file stands alone. Coordinates are drawing pixels; the viewBox is the drawing
// grown, where needed, to whole pixels around every dot and label, so none is cut off at an edge.
#pragma once

#include "meshing/key_shape.h"
#include "multimesh/multimesh.h"

#include <string>
#include <vector>

namespace ib {

// A label's extent in drawing pixels: [x0, x1] x [y0, y1], y down.
struct TextBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// The box that `text` (UTF-8) set in sans-serif at fontSize px takes, its baseline at y, starting at
// x (anchorEnd false) or ending there (true). An estimate from the characters, on the wide side:
// em per character 0.4 for narrow ones (i, l, t, r, punctuation), 1 for m, w, M, W and anything
// beyond ASCII, 0.8 for other capitals, 0.65 otherwise (DejaVu Sans: digits 0.64, o 0.60, D 0.77);
// 0.8 em above the baseline and 0.25 em below it.
TextBox estimatedTextBox(const std::string& text, double x, double y, double fontSize, bool anchorEnd);

// An interior feature of the key, drawn like a feature, with its disc's circle dashed when it has a
// radius (scene field keys[].interior_features).
struct InteriorMark {
  std::string name;
  Eigen::Vector2d at = Eigen::Vector2d::Zero();  // drawing px
  double radius = 0;                             // px; 0: a plain point
};

// Screen pixels the picture's larger side is shown at, at least (drawings smaller than this are
// shown at a whole multiple of their size, at most 16x).
constexpr int kShownPixels = 768;
// The whole multiple a width x height drawing is shown at: 1 from kShownPixels up.
int svgScale(int width, int height);

// drawingPng: the drawing's PNG bytes; width, height: its size in pixels. The SVG's width and
// height are the picture's size times svgScale (its viewBox in drawing pixels).
std::string meshSvg(const Multimesh& mesh, int key, const KeyShape& shape, const std::string& drawingPng, int width,
                    int height, const std::vector<InteriorMark>& interior = {});

}  // namespace ib
