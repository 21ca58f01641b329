// Keys are the drawings (issue: faithful pixels). The mesh's boundary follows each key's traced
// outline, but a drawing's antialiased edge, and whatever it draws a pixel or two beyond the
// outline, lies partly outside it: drawn by the mesh alone, a key frame loses it. A KeyRim is a
// band of triangles outside the mesh boundary, h drawing px wide: a quad outward from every
// boundary edge and a fan of spokes round every boundary vertex. Its outer points move with the
// frame's boundary (offsets along the boundary's outward normals in the frame's positions), and its
// UVs in key i are the same offsets in key i's positions, so at w = e_i the rim lies exactly where
// key i's drawing has its edge. The renderer draws it after the mesh, only where the frame has
// drawn nothing (a stencil), with the keys' drawings as drawn and faded by render::keyness: at a key
// the frame is the drawing, and away from the keys the silhouette is the mesh's own edge as before
// (docs/rendering.md, "Keys are the drawings").
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace ib::render {

struct KeyRimOptions {
  // Drawing px: how far the rim reaches outside the mesh boundary. Covers the drawing's antialiased
  // edge (about a pixel past its traced outline), how far the boundary strays from that outline
  // (under half a pixel), a soft brush's fringe and a sharp tip the traced outline cuts short (at 3
  // px hexagon-star-thin's star tips still lost up to 4/255; `inbetween bench keys`). Default 5.
  double width = 5;
};

struct KeyRim {
  // Rim points are numbered after the mesh's vertices: point j is vertex vertexCount + j.
  struct Point {
    int vertex = 0;  // the boundary vertex it is offset from
    int edge = -1;   // offset along this boundary edge's outward normal (index into edges), or -1:
    double angle = 0;  // along the vertex's outward direction turned by `angle` (radians)
  };
  std::vector<std::array<int, 3>> edges;  // the boundary edges {a, b, c}: c the third vertex of a's and b's triangle
  std::vector<Point> points;
  std::vector<Triangle> triangles;        // over mesh vertices and rim points (vertexCount + j)
  double width = 5;                       // drawing px
};

// The rim of `mesh` (its boundary edges, cuts' sides included).
KeyRim keyRimOf(const Multimesh& mesh, const KeyRimOptions& options = {});

// The rim points (rim.points.size() x 2) for positions x (n x 2, drawing px): each an offset of
// rim.width from its vertex along its direction in x.
Eigen::MatrixX2d rimPoints(const KeyRim& rim, const Eigen::MatrixX2d& x);

// How much a frame with interpolation weights w (m, summing to 1) shows the keys' own drawings:
// 1 at a key's weight e_i, falling smoothly (smoothstep) to 0 once the largest weight is `window`
// below 1. Default window 0.1: the first and last tenth of a segment between two keys.
double keyness(const Eigen::VectorXd& w, double window = 0.1);

}  // namespace ib::render
