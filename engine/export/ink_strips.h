// An opened cut's outline ink as geometry, for clients that have no artwork shader of ours (the
// glTF export; the renderer draws the same ink per fragment, shaders/artwork.frag). Along every
// side of a cut whose drawings have an outline line (render::CutInks), a strip of the line's width
// inside the shape: its outer edge is the side, its inner edge the side moved inward by the width
// in every frame, so the line keeps its drawn width however the mesh stretches. Its colour is the
// line's, its alpha per vertex the renderer's (render::inkAlpha): none where the cut is glued, and
// less as the keys that draw the cut open, with their own line, take the weight. CPU only.
#pragma once

#include "output/cut_ink.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace ib::gltf {

struct InkStrips {
  std::vector<Triangle> triangles;  // over the strip vertices
  std::vector<int> source;          // [strip vertex]: the mesh vertex on the side it moves with
  std::vector<int> cut;             // [strip vertex]: its cut (index into CutInks::cuts)
  // [strip vertex]: empty on the side; for an inner vertex, the sides (one face of the cut, meeting
  // at the source) whose inward normals, summed, give the direction it is moved along.
  std::vector<std::vector<int>> inward;
  // [strip vertex]: for an inner vertex at a chain's end on the outline, its neighbours along the
  // outline: the strip's end then runs along the outline (the inner vertex slides along it to the
  // line's width from the side), so the ink does not stick out of the shape there.
  std::vector<std::vector<int>> along;
  int vertexCount() const { return static_cast<int>(source.size()); }
};

// The strips of every side of `inks` (none when no cut has ink) on the mesh of `triangles`.
InkStrips inkStripsOf(const render::CutInks& inks, const std::vector<Triangle>& triangles);

// The strip vertices at mesh positions x (n x 2, drawing px): strip vertices x 2, drawing px. An
// inner vertex lies the line's width from its sides, measured along their summed inward normal.
Eigen::MatrixX2d inkStripPositions(const InkStrips& strips, const render::CutInks& inks, const Eigen::MatrixX2d& x);

// RGBA per strip vertex (4 floats each; colour linear, as glTF's COLOR_0, alpha straight) at a frame's per-vertex closure (render::weldCuts,
// n) and interpolation weights (m).
std::vector<float> inkStripColours(const InkStrips& strips, const render::CutInks& inks, const std::vector<float>& closure,
                                   const Eigen::VectorXd& weights);

}  // namespace ib::gltf
