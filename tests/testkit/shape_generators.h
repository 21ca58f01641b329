// Meshes built in code: a triangulated rectangle and smooth, orientation-preserving
// deformations of it (bend, stretch, wave), and two squares glued by a cut. Used by the tests and
// by `inbetween bench`.
#pragma once

#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

struct GridMesh {
  Eigen::MatrixX2d points;           // nx * ny vertices, row-major from (0, 0), y up
  std::vector<Triangle> triangles;   // 2 (nx-1)(ny-1), counter-clockwise (positive area)
  std::vector<int> boundary;         // vertices on the rectangle's outline
};

// nx x ny vertices covering [0, width] x [0, height]; diagonals alternate to avoid bias.
GridMesh rectangleGrid(int nx, int ny, double width, double height);

// Bends a strip lying along x (centred on its bounding box) into a circular arc spanning
// `angle` radians, ends curling towards +y. Requires the arc radius to exceed half the height.
Eigen::MatrixX2d bendStrip(const Eigen::MatrixX2d& X, double angle);

// Stretches along x by up to `factor` at the right end and tapers y there by `taper`.
Eigen::MatrixX2d stretchStrip(const Eigen::MatrixX2d& X, double factor, double taper);

// Shears y by amplitude * sin(2 pi periods * x / length): area-preserving.
Eigen::MatrixX2d waveStrip(const Eigen::MatrixX2d& X, double amplitude, double periods);

// A strip of about `vertices` vertices (aspect 4:1) with `keys` keys (1..4): rest, 180-degree
// bend, stretch, wave. Key 0 is the rest strip. No cohesive pairs.
Multimesh benchmarkStrip(int vertices, int keys);

// Two unit squares side by side (side x side vertices each, own vertices along the seam x = 1).
// Key 0: glued, the seam sides collocated and paired as cohesive edges (side - 1 pairs). Key 1:
// apart by `gap`, each seam side bulging towards the other by `bulge` so gluing them costs
// deformation. Vertex j * side + side - 1 (left square) and side^2 + j * side (right) are the
// seam's j-th pair from the bottom.
Multimesh gluedSquares(int side, double gap, double bulge);

}  // namespace ib
