#include "export/position_codec.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ib::gltf {

namespace {
constexpr double kShortMax = 32767.0;
double asFloat(double v) { return static_cast<double>(static_cast<float>(v)); }
}  // namespace

PositionCodec::PositionCodec(std::array<int, 2> canvas, double pixelsPerUnit, bool quantized, const Eigen::MatrixX2d& base,
                             const std::vector<Eigen::MatrixX2d>& frames)
    : canvas_(canvas), pixelsPerUnit_(pixelsPerUnit), quantized_(quantized), base_(base) {
  if (canvas[0] <= 0 || canvas[1] <= 0 || !(pixelsPerUnit > 0) || !std::isfinite(pixelsPerUnit))
    throw std::invalid_argument("PositionCodec: canvas and pixels per unit must be positive");
  if (!quantized_) return;
  // c: the centre of the base's bounding box, so local base coordinates stay small; k: the largest
  // delta coordinate over all frames (at least a thousandth of a pixel, so a still has a scale).
  const Eigen::MatrixX3d world = local(base_);
  for (int axis = 0; axis < 2; ++axis)
    translation_[axis] = 0.5 * (world.col(axis).minCoeff() + world.col(axis).maxCoeff());
  double largest = 1e-3 / pixelsPerUnit;
  for (const Eigen::MatrixX2d& frame : frames)
    largest = std::max(largest, (frame - base_).cwiseAbs().maxCoeff() / pixelsPerUnit);
  scale_ = largest;
}

Eigen::MatrixX3d PositionCodec::local(const Eigen::MatrixX2d& px) const {
  Eigen::MatrixX3d out(px.rows(), 3);
  out.col(0) = ((px.col(0).array() - 0.5 * canvas_[0]) / pixelsPerUnit_ - translation_[0]) / scale_;
  out.col(1) = ((0.5 * canvas_[1] - px.col(1).array()) / pixelsPerUnit_ - translation_[1]) / scale_;
  out.col(2).setZero();
  return out;
}

Eigen::MatrixX2d PositionCodec::pixels(const Eigen::MatrixX3d& l) const {
  Eigen::MatrixX2d out(l.rows(), 2);
  out.col(0) = (l.col(0).array() * scale_ + translation_[0]) * pixelsPerUnit_ + 0.5 * canvas_[0];
  out.col(1) = 0.5 * canvas_[1] - (l.col(1).array() * scale_ + translation_[1]) * pixelsPerUnit_;
  return out;
}

Eigen::MatrixX3d PositionCodec::storedBase() const { return local(base_).unaryExpr(&asFloat); }

Eigen::MatrixX3d PositionCodec::storedDelta(const Eigen::MatrixX2d& frame) const {
  // The delta that brings the stored base to the frame (so float rounding of the base is undone).
  const Eigen::MatrixX3d delta = local(frame) - storedBase();
  if (!quantized_) return delta.unaryExpr(&asFloat);
  return delta.unaryExpr([](double d) { return std::round(std::clamp(d, -1.0, 1.0) * kShortMax) / kShortMax; });
}

std::vector<float> PositionCodec::base() const {
  const Eigen::MatrixX3d b = storedBase();
  std::vector<float> out(static_cast<size_t>(b.rows()) * 3);
  for (Eigen::Index v = 0; v < b.rows(); ++v)
    for (int a = 0; a < 3; ++a) out[3 * v + a] = static_cast<float>(b(v, a));
  return out;
}

std::vector<float> PositionCodec::floatDeltas(const Eigen::MatrixX2d& frame) const {
  const Eigen::MatrixX3d d = storedDelta(frame);
  std::vector<float> out(static_cast<size_t>(d.rows()) * 3);
  for (Eigen::Index v = 0; v < d.rows(); ++v)
    for (int a = 0; a < 3; ++a) out[3 * v + a] = static_cast<float>(d(v, a));
  return out;
}

std::vector<int16_t> PositionCodec::shortDeltas(const Eigen::MatrixX2d& frame) const {
  const Eigen::MatrixX3d d = storedDelta(frame);
  std::vector<int16_t> out(static_cast<size_t>(d.rows()) * 4, 0);
  for (Eigen::Index v = 0; v < d.rows(); ++v)
    for (int a = 0; a < 3; ++a) out[4 * v + a] = static_cast<int16_t>(std::lround(d(v, a) * kShortMax));
  return out;
}

Eigen::MatrixX2d PositionCodec::decoded(const Eigen::MatrixX2d& frame) const {
  return pixels(storedBase() + storedDelta(frame));
}

}  // namespace ib::gltf
