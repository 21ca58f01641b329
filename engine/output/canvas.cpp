#include "output/canvas.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace ib::render {

namespace {

const char* const kForms = "give drawing (the drawings' canvas, the default), fit (the whole animation) or WxH+X+Y in drawing pixels, e.g. 640x480-64+0";

// A whole number with an optional sign at `text[at]`; advances `at`. False when there is none.
bool readInteger(const std::string& text, size_t& at, bool signedAllowed, long& out) {
  const size_t start = at;
  if (signedAllowed && at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
  const size_t digits = at;
  while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) ++at;
  if (at == digits || at - digits > 6) return false;
  out = std::stol(text.substr(start, at - start));
  return true;
}

}  // namespace

CanvasChoice parseCanvas(const std::string& text) {
  CanvasChoice choice;
  if (text == "drawing") return choice;
  if (text == "fit") {
    choice.kind = CanvasChoice::Kind::kFit;
    return choice;
  }
  size_t at = 0;
  long w = 0, h = 0, x = 0, y = 0;
  const bool ok = readInteger(text, at, false, w) && at < text.size() && (text[at] == 'x' || text[at] == 'X') &&
                  readInteger(text, ++at, false, h) && at < text.size() && (text[at] == '+' || text[at] == '-') &&
                  readInteger(text, at, true, x) && at < text.size() && (text[at] == '+' || text[at] == '-') &&
                  readInteger(text, at, true, y) && at == text.size();
  if (!ok) throw std::invalid_argument("'" + text + "' is not a canvas: " + kForms);
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throw std::invalid_argument("'" + text + "': the width and height must be 1..16384 drawing pixels; " + kForms);
  choice.kind = CanvasChoice::Kind::kRect;
  choice.rect = {double(x), double(y), double(x + w), double(y + h)};
  return choice;
}

ViewBox canvasBox(const CanvasChoice& choice, const ViewBox& drawingCanvas, const ViewBox& animation) {
  switch (choice.kind) {
    case CanvasChoice::Kind::kDrawing:
      return drawingCanvas;
    case CanvasChoice::Kind::kRect:
      return choice.rect;
    case CanvasChoice::Kind::kFit:
      break;
  }
  // Whole pixels, so that a key still lies on the drawing's pixel grid.
  return {std::floor(animation.x0 - choice.margin), std::floor(animation.y0 - choice.margin), std::ceil(animation.x1 + choice.margin),
          std::ceil(animation.y1 + choice.margin)};
}

std::array<int, 2> canvasPixels(const ViewBox& box) {
  return {std::max(1, static_cast<int>(std::ceil(box.x1 - box.x0 - 1e-9))), std::max(1, static_cast<int>(std::ceil(box.y1 - box.y0 - 1e-9)))};
}

void CanvasReach::add(int index, const Eigen::MatrixX2d& x, const ViewBox& box) {
  if (x.rows() == 0) return;
  const double past = std::max({box.x0 - x.col(0).minCoeff(), box.y0 - x.col(1).minCoeff(), x.col(0).maxCoeff() - box.x1,
                                x.col(1).maxCoeff() - box.y1});
  if (past <= 0.5) return;
  frames.push_back(index);
  farthest = std::max(farthest, past);
}

std::string CanvasReach::message(int framesRendered) const {
  if (frames.empty()) return "";
  // Runs of consecutive frames, "20-30, 41".
  std::string runs;
  for (size_t i = 0; i < frames.size();) {
    size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    if (!runs.empty()) runs += ", ";
    runs += std::to_string(frames[i]) + (j > i ? "-" + std::to_string(frames[j]) : "");
    i = j + 1;
  }
  return std::to_string(frames.size()) + " of " + std::to_string(framesRendered) + " frames reach past the canvas (" +
         (frames.size() == 1 ? "frame " : "frames ") + runs + ") by up to " + std::to_string(static_cast<int>(std::ceil(farthest))) +
         " drawing px, and are cut off there: --canvas fit shows the whole animation, or give a larger --canvas WxH+X+Y";
}

}  // namespace ib::render
