// Zoom and pan of the player's canvas, as pure arithmetic: the drawing's canvas fitted into the
// part of the window the panels leave free, zoomed about a point and panned by a drag, then
// widened to the whole window (the presenter maps its view box onto every window pixel).
#pragma once

#include "output/render_mesh.h"

#include <Eigen/Core>

namespace ib::play {

// A rectangle of window pixels, x0 < x1, y0 < y1 (y down).
struct PixelRect {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  bool contains(double x, double y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

class ViewNavigation {
 public:
  void fit();                                   // zoom 1, no pan: the content fills the canvas
  double zoom() const { return zoom_; }         // 1 = fitted; in [1/16, 64]
  const Eigen::Vector2d& pan() const { return pan_; }

  // The view box for the whole window of `width` x `height` pixels that shows `content` (drawing
  // pixels) fitted into `canvas` (with a 5% margin) at the current zoom and pan.
  render::ViewBox windowView(const render::ViewBox& content, const PixelRect& canvas, int width, int height) const;
  // Zooms by `factor` keeping the drawing point under window pixel (x, y) where it is.
  void zoomAt(double factor, double x, double y, const render::ViewBox& content, const PixelRect& canvas, int width,
              int height);
  // Moves the picture by (dx, dy) window pixels.
  void drag(double dx, double dy, const render::ViewBox& content, const PixelRect& canvas, int width, int height);

 private:
  double zoom_ = 1;
  Eigen::Vector2d pan_ = Eigen::Vector2d::Zero();  // drawing pixels: the visible centre minus the fitted one
};

// Window pixel of drawing point `p` under `view` on a `width` x `height` window, and back.
Eigen::Vector2d toWindow(const render::ViewBox& view, int width, int height, const Eigen::Vector2d& p);

}  // namespace ib::play
