#include "player/view_navigation.h"

#include <algorithm>

namespace ib::play {

namespace {

constexpr double kMinZoom = 1.0 / 16, kMaxZoom = 64;

// Drawing pixels per window pixel of the fitted content at zoom 1, and the fitted box's centre.
struct Fit {
  double unitsPerPixel = 1;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
};

Fit fitted(const render::ViewBox& content, const PixelRect& canvas) {
  const int cw = std::max(1, static_cast<int>(canvas.x1 - canvas.x0)), ch = std::max(1, static_cast<int>(canvas.y1 - canvas.y0));
  const render::ViewBox box = render::fitView(content, cw, ch, 0.05);
  return {(box.x1 - box.x0) / cw, {0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1)}};
}

}  // namespace

void ViewNavigation::fit() {
  zoom_ = 1;
  pan_.setZero();
}

render::ViewBox ViewNavigation::windowView(const render::ViewBox& content, const PixelRect& canvas, int width,
                                           int height) const {
  const Fit fit = fitted(content, canvas);
  const double s = fit.unitsPerPixel / zoom_;
  const Eigen::Vector2d centre = fit.centre + pan_;
  // The canvas's centre pixel shows `centre`.
  const double cx = 0.5 * (canvas.x0 + canvas.x1), cy = 0.5 * (canvas.y0 + canvas.y1);
  render::ViewBox view;
  view.x0 = centre.x() - cx * s;
  view.y0 = centre.y() - cy * s;
  view.x1 = view.x0 + width * s;
  view.y1 = view.y0 + height * s;
  return view;
}

void ViewNavigation::zoomAt(double factor, double x, double y, const render::ViewBox& content, const PixelRect& canvas,
                            int width, int height) {
  const render::ViewBox before = windowView(content, canvas, width, height);
  const double sBefore = (before.x1 - before.x0) / width;
  const Eigen::Vector2d under(before.x0 + x * sBefore, before.y0 + y * sBefore);
  zoom_ = std::clamp(zoom_ * factor, kMinZoom, kMaxZoom);
  const render::ViewBox after = windowView(content, canvas, width, height);
  const double sAfter = (after.x1 - after.x0) / width;
  const Eigen::Vector2d now(after.x0 + x * sAfter, after.y0 + y * sAfter);
  pan_ += under - now;
}

void ViewNavigation::drag(double dx, double dy, const render::ViewBox& content, const PixelRect& canvas, int width,
                          int height) {
  const render::ViewBox view = windowView(content, canvas, width, height);
  const double s = (view.x1 - view.x0) / width;
  pan_ -= Eigen::Vector2d(dx * s, dy * s);
}

Eigen::Vector2d toWindow(const render::ViewBox& view, int width, int height, const Eigen::Vector2d& p) {
  return {(p.x() - view.x0) / (view.x1 - view.x0) * width, (p.y() - view.y0) / (view.y1 - view.y0) * height};
}

}  // namespace ib::play
