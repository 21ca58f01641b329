// Quality conforming Delaunay triangulation of a region bounded by polygons (CGAL's
// Delaunay_mesher_2), with interior constraint polylines (cuts) kept as mesh edges.
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace ib {

struct ConformingMeshOptions {
  double maxEdgeLength = 8;  // px: no triangle edge longer than this. Default 8.
  double shapeBound = 0.125;  // CGAL's B = 1 / (4 sin^2 smallest angle); 0.125 is about 20.7 degrees. Default 0.125.
  int maxVertices = 2000000;  // refinement stops with an error past this many vertices. Default 2e6.
};

struct ConformingMesh {
  std::vector<Eigen::Vector2d> points;    // vertices, input points first (same indices)
  std::vector<Triangle> triangles;        // counter-clockwise (positive signedArea)
  std::vector<std::array<int, 2>> cuts;   // mesh edges along the cut constraints
};

// points: the input vertices. boundary: segments bounding the region (each once; the region is
// what an odd number of them encloses). cuts: segments inside the region that must stay mesh
// edges. Steiner points the mesher adds (on segments too) come after the input points. Throws
// InputError when the boundary is degenerate or refinement exceeds maxVertices.
ConformingMesh conformingMesh(const std::vector<Eigen::Vector2d>& points,
                              const std::vector<std::array<int, 2>>& boundary,
                              const std::vector<std::array<int, 2>>& cuts, const ConformingMeshOptions& options);

}  // namespace ib
