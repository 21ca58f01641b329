// What part of the drawing plane a rendered frame shows (issue: faithful pixels, "the canvas"):
// the drawings' canvas, the whole animation fitted with a margin, or a rectangle the user gives.
// Frames can reach past the drawings' canvas (a tail that whips out of it); render says how many
// and which option keeps them (canvasReach), rather than cutting them off without a word.
#pragma once

#include "output/render_mesh.h"

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace ib::render {

struct CanvasChoice {
  enum class Kind {
    kDrawing,  // the drawings' canvas, (0, 0) to the largest drawing's size: frames line up with the drawings' pixels
    kFit,      // every frame's shape, grown by `margin`, its corners on whole drawing pixels
    kRect,     // `rect`, drawing px
  };
  Kind kind = Kind::kDrawing;  // default: the drawings' canvas
  ViewBox rect;                // kRect: x0, y0, x1, y1 in drawing px
  double margin = 8;           // kFit: drawing px round the animation (covers the keys' rims, key_rim.h). Default 8.
};

// Parses `--canvas`: "drawing", "fit" or "WxH+X+Y" (drawing px, X and Y may be negative, e.g.
// 640x480-64+0). Throws std::invalid_argument with what is wrong and the three forms.
CanvasChoice parseCanvas(const std::string& text);

// The box the choice shows: `drawingCanvas` is (0, 0, W, H) of the largest drawing; `animation`
// the bounds of every frame's positions (boundsOf; only read for kFit).
ViewBox canvasBox(const CanvasChoice& choice, const ViewBox& drawingCanvas, const ViewBox& animation);

// The picture size showing `box` at one target pixel per drawing pixel (rounded up, at least 1).
std::array<int, 2> canvasPixels(const ViewBox& box);

// How the frames of an animation reach past a box.
struct CanvasReach {
  std::vector<int> frames;  // frame indices whose shape leaves the box by more than half a pixel, ascending
  double farthest = 0;      // drawing px: the most any of them reaches past it
  // Adds frame `index` at positions x (n x 2, drawing px) against `box`.
  void add(int index, const Eigen::MatrixX2d& x, const ViewBox& box);
  // "" when no frame leaves; else e.g. "11 of 54 frames reach past the canvas (frames 20-30) by up
  // to 37 drawing px, and are cut off there: --canvas fit shows the whole animation, or ...".
  std::string message(int framesRendered) const;
};

}  // namespace ib::render
