// The reference key's triangulation (docs/design.md, "Multimesh"): its resampled boundary, cut sides as
// constraints, meshed by CGAL, then cut open so each cut side has its own vertices. Every boundary
// vertex is tagged with the shared-boundary arc it lies on and its fraction along that arc, so the
// same vertex can be placed in every key.
#pragma once

#include "meshing/conforming_mesh.h"
#include "meshing/shared_boundary.h"

#include <vector>

namespace ib {

struct BoundaryTag {
  int arc = -1;   // shared-boundary arc, or -1 for an interior vertex
  double u = 0;   // fraction of the arc's length from its start, in [0, 1)
};

struct ReferenceMesh {
  std::vector<Eigen::Vector2d> points;   // planar positions: every triangle positive (px)
  std::vector<Triangle> triangles;       // counter-clockwise
  std::vector<BoundaryTag> tags;         // per vertex
  std::vector<std::vector<int>> arcChains;  // [arc]: its vertices by increasing u (first at u = 0)
  std::vector<int> arcEnd;                  // [arc]: the vertex where it ends (the next arc's first)
  std::vector<int> interior;                // [interior feature]: its vertex, exactly at the given point
};

// Resamples the reference key's boundary (each arc into its segments), meshes it with
// `options` with a vertex at each of `interior` (the interior features in the reference key, px,
// inside the shape and apart from its boundary), and cuts it open. A boundary point the mesher
// adds to one side of a cut is added to the other side too, and an interior edge between two
// pinned vertices (boundary or interior feature) is split, so that no triangle has all three
// corners pinned.
ReferenceMesh meshReference(const SharedBoundary& boundary, int reference, const ConformingMeshOptions& options,
                            const std::vector<Eigen::Vector2d>& interior = {});

}  // namespace ib
