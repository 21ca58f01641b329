// Each key's drawing as the renderer and the glTF export texture it, so that the silhouette of
// every frame is the mesh's own edge (docs/rendering.md, "Silhouettes"). Along a key's mesh
// boundary its drawing is either antialiased (partly transparent) or, where a boundary edge bridges
// a concave corner, paper; an inbetween samples those texels well inside its silhouette where
// another key is opaque, and the weighted blend shows grey, half-transparent patches. Within a
// band around the key's mesh boundary (both sides) the opacity is raised to that of the drawing's
// interior next to it, and texels that were transparent or nearly so take the colour of the
// nearest solid texel; the mesh's coverage (multisampled) then draws the antialiased edge. Away
// from the boundary the drawing is unchanged, translucent interior detail included.
#pragma once

#include "core/png_image.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib::render {

struct SilhouetteOptions {
  // Drawing px: half-width of the band around the mesh boundary whose opacity comes from the
  // interior. Covers the drawing's antialiased rim (about a pixel) plus how far the boundary
  // edges stray from the traced outline (under half a pixel). 0 leaves the drawing as it is.
  // Default 2.
  double band = 2;
};

// `drawing` (straight alpha) with the band around the mesh boundary at `positions` (n x 2,
// drawing px; texel (i, j) has its centre at (i + 0.5, j + 0.5)) made as opaque as the interior
// beside it. `boundary`: the mesh's boundary edges (Multimesh::boundaryEdges).
RgbaImage silhouetteArtwork(const RgbaImage& drawing, const std::vector<Triangle>& triangles,
                            const std::vector<Edge>& boundary, const Eigen::MatrixX2d& positions,
                            const SilhouetteOptions& options = {});

}  // namespace ib::render
