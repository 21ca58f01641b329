// Drawing pixels to glTF positions and back, as a client decodes them: the frame's units, the
// optional 16-bit quantization of the morph targets (KHR_mesh_quantization) and float32 storage.
//
// glTF point of drawing pixel (px, py) (y down, origin at the canvas's top-left, canvas W x H):
//   X = (px - W/2) / p,  Y = (H/2 - py) / p,  Z = 0,   p = pixels per unit.
// Quantized, the mesh's node carries translation c and uniform scale k: the base positions are
// float local coordinates (X - c) / k, and each morph target's deltas are normalized signed
// shorts q / 32767 of local units, so k is the largest delta coordinate (a step of k / 32767).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace ib::gltf {

class PositionCodec {
 public:
  // canvas in drawing pixels (> 0), pixelsPerUnit > 0. With `quantized`, the node transform is
  // chosen to fit the deltas of every frame from `base` (n x 2 each, drawing pixels).
  PositionCodec(std::array<int, 2> canvas, double pixelsPerUnit, bool quantized, const Eigen::MatrixX2d& base,
                const std::vector<Eigen::MatrixX2d>& frames);

  bool quantized() const { return quantized_; }
  const std::array<double, 3>& translation() const { return translation_; }  // node translation c (glTF units)
  double scale() const { return scale_; }                                     // node scale k (1 unquantized)

  // The base positions as stored: n x 3 float local coordinates.
  std::vector<float> base() const;
  // A frame's morph target as stored: n x 3 floats (unquantized) or n x 4 shorts (quantized; the
  // fourth is padding, for 4-byte vertex alignment).
  std::vector<float> floatDeltas(const Eigen::MatrixX2d& frame) const;
  std::vector<int16_t> shortDeltas(const Eigen::MatrixX2d& frame) const;
  // Where a client puts the frame's vertices when its target has weight 1, back in drawing pixels.
  Eigen::MatrixX2d decoded(const Eigen::MatrixX2d& frame) const;

 private:
  Eigen::MatrixX3d local(const Eigen::MatrixX2d& pixels) const;      // n x 3 local coordinates
  Eigen::MatrixX2d pixels(const Eigen::MatrixX3d& local) const;      // back to drawing pixels
  Eigen::MatrixX3d storedBase() const;                               // base as float32, in doubles
  Eigen::MatrixX3d storedDelta(const Eigen::MatrixX2d& frame) const; // delta as the client reads it

  std::array<int, 2> canvas_;
  double pixelsPerUnit_;
  bool quantized_;
  Eigen::MatrixX2d base_;
  std::array<double, 3> translation_{0, 0, 0};
  double scale_ = 1;
};

}  // namespace ib::gltf
