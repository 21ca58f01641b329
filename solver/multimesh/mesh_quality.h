// Quality of a multimesh as Comesh Optimization sees it (paper section 4.1): triangle angles per
// key, and MIPS distortion of the map between cyclically neighbouring keys.
#pragma once

#include "multimesh/multimesh.h"

#include <vector>

namespace ib {

struct KeyQuality {
  double smallestAngle = 0;   // degrees, over all triangles
  double meanSmallestAngle = 0;  // degrees: mean over triangles of each triangle's smallest angle
  double shareUnder20 = 0;    // fraction of triangles whose smallest angle is under 20 degrees
  int under20 = 0;            // how many triangles those are
};

// MIPS of the map from key `from` to key `to`, per triangle s1/s2 + s2/s1 (2 when conformal).
struct MapQuality {
  int from = 0, to = 0;
  double mipsMean = 0;  // weighted by triangle area in `from` (eq. 5 over the total area)
  double mipsMax = 0;
};

struct MultimeshQuality {
  std::vector<KeyQuality> keys;  // [key]
  std::vector<MapQuality> maps;  // cyclic neighbours, both directions: i -> i+1 and i+1 -> i
};

MultimeshQuality measureQuality(const Multimesh& mesh);

// The angles of `triangles` at positions x (vertices x 2, px), e.g. one key of a mesh being edited.
KeyQuality keyQuality(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& x);

}  // namespace ib
