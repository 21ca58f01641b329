// How closely each key's mesh boundary follows its own outline: the silhouette an animator sees at
// a key is the mesh's, so a boundary edge that cuts across a corner of the drawing clips it, and
// one that bridges a concave corner covers paper (docs/drawings-to-multimesh.md, "Corners").
#pragma once

#include "meshing/key_shape.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

struct OutlineFit {
  // px: the largest distance, both ways, between the key's shape loops (its traced outline after
  // features and cuts) and the mesh's boundary edges at the key's positions (a Hausdorff distance,
  // each side sampled every 0.25 px).
  double largest = 0;
  Eigen::Vector2d where = Eigen::Vector2d::Zero();  // px: the point of either side that is that far
};

// [key]: how closely the mesh's boundary in key i follows shapes[i]. Throws std::invalid_argument
// when shapes and keys differ in count.
std::vector<OutlineFit> outlineFits(const Multimesh& mesh, const std::vector<KeyShape>& shapes);

}  // namespace ib
