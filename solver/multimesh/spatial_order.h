// Orders for memory locality: mesh loops gather vertex positions by index, and a mesher numbers
// its vertices in no spatial order (CGAL's 17k-vertex square-hexagon: edges join vertices 6,550
// apart in the numbering on average, out of 17,054), so most gathered loads miss the cache.
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

// The points in the order of a Hilbert curve over their bounding box (a 2^16 x 2^16 grid, ties
// by index): order[k] is the index of the k-th point. Points near each other on the curve are
// near each other in the plane.
std::vector<int> hilbertOrder(const std::vector<Eigen::Vector2d>& points);

// Triangles in the order of their smallest corner (then the others): with vertices in a spatial
// order, triangles sharing vertices come close together. order[k] is the index of the k-th.
std::vector<int> triangleOrder(const std::vector<Triangle>& triangles);

}  // namespace ib
