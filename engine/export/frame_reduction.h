// Dropping frames a client can rebuild: a client blends the morph targets of the kept frames on
// either side linearly in time, so a frame can go when that blend lies within the bound of it at
// every vertex. The bound is checked at every original frame time against the positions as the
// client decodes the kept frames (quantization included), so it is a guarantee, not an estimate.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace ib::gltf {

struct FrameReduction {
  std::vector<int> kept;  // indices into the frames, increasing; always the first and the last
  double maxError = 0;    // drawing pixels: the largest vertex distance over every frame time
};

// exact[f]: frame f (n x 2, drawing pixels); decoded(f): where a client puts frame f's vertices
// when its target is kept; times: increasing, s. maxError >= 0, in drawing pixels; 0 keeps every
// frame (and still measures the decoding error). Greedy: from each kept frame, the next kept one
// is the farthest whose blend with it reproduces every frame between within the bound.
FrameReduction reduceFrames(const std::vector<Eigen::MatrixX2d>& exact,
                            const std::function<Eigen::MatrixX2d(int frame)>& decoded, const std::vector<double>& times,
                            double maxError);

}  // namespace ib::gltf
