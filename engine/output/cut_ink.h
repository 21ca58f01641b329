// The ink of a drawing's outline where a cut meets it: the colour and width of the dark line an
// artist drew round the shape, so that an edge a cut opens can be drawn with the same line
// (issue 46, item 3). CPU only.
#pragma once

#include "core/png_image.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <vector>

namespace ib::render {

struct OutlineInk {
  bool found = false;                     // the drawing has an outline line there
  std::array<float, 4> colour{0, 0, 0, 1};  // straight RGBA in [0, 1]: the line's mean colour
  double width = 0;                       // drawing px, across the line
};

// Marches from `at` (drawing px, on or near the outline) along `inward` (into the shape, any
// length) from 4 px outside to 24 px inside, in half-pixel steps, bilinear samples. The line is
// the run of opaque samples (alpha >= 1/2) from the first one whose luminance stays below the
// fill's (the median of the opaque samples 8 to 24 px in) by at least `contrast`; found when it is
// at least 1 px wide and the fill is at least 2 px deeper than it ends.
OutlineInk outlineInk(const RgbaImage& drawing, const Eigen::Vector2d& at, const Eigen::Vector2d& inward,
                      double contrast = 0.15);

// The direction into the shape at `at` (drawing px): up the drawing's alpha, its gradient summed
// over the pixels within `radius` px (so a 1 px antialiased edge and a blurry one alike give the
// outline's normal). Zero where the alpha is flat.
Eigen::Vector2d inwardNormal(const RgbaImage& drawing, const Eigen::Vector2d& at, double radius = 3);

// Every cut's ink and where it is drawn, fixed for a multimesh and its drawings: a cut is a chain of
// cohesive pairs end to end closed in the same keys; its ink is the narrowest of the outline's reads
// at the chain's two ends (the pair vertices that are also on the outline: boundary vertices of
// the key) in every key that closes it. Its sides are the pairs' edges {a, b} and {c, d}.
struct CutInks {
  struct Cut {
    OutlineInk ink;              // found = false: the drawings have no line there; not drawn
    std::vector<char> closedIn;  // [key]: the key closes the cut
  };
  std::vector<Cut> cuts;
  std::vector<Edge> sides;     // side edges {a, b}
  std::vector<int> sideCut;    // [side]: its cut
  std::vector<int> sideApex;   // [side]: the third vertex of the side's triangle (into the shape)
  // [side]: its inward unit normal in the first key that closes its cut (drawing px); there the
  // cut's two faces lie on one another, facing opposite ways, which tells them apart.
  std::vector<Eigen::Vector2d> sideRestNormal;
  // Vertices that may lie within a line's width of a side: the sides' vertices and the vertices
  // that share a triangle with them. near[v] lists the sides to measure v against ([] elsewhere).
  std::vector<std::vector<int>> near;
};

// drawings: [key], the keys' drawings as read (before silhouetteArtwork), in the multimesh's
// pixels.
CutInks cutInksOf(const Multimesh& mesh, const std::vector<RgbaImage>& drawings);

// Side s's inward unit normal at positions x (n x 2): perpendicular to it, towards its triangle's
// apex (0 for a side of no length).
Eigen::Vector2d sideNormal(const CutInks& inks, int side, const Eigen::MatrixX2d& x);

// o per cut: the total of `weights` (m) over the keys that draw the cut open.
std::vector<double> openWeights(const CutInks& inks, const Eigen::VectorXd& weights);

// How much of a cut's ink a frame draws at a side vertex: (1 - closure) (1 - o).
inline float inkAlpha(float closure, double open) {
  return static_cast<float>((1.0 - closure) * std::clamp(1.0 - open, 0.0, 1.0));
}

// One frame's ink per vertex, for the artwork shader: its distance to the nearest side (target
// pixels, large away from cuts), the ink's colour (straight RGB) and width (target pixels), and
// how much of it to draw, alpha = (1 - closure) (1 - o): nothing where the cut is shut, and less
// as the keys that open it, which draw their own line there, take the weight o.
struct InkFrame {
  std::vector<float> distance, alpha, width;
  std::vector<std::array<float, 3>> colour;
};
// x: n x 2 positions (drawing pixels); closure: weldCuts' per vertex; weights: m.
InkFrame inkFrame(const CutInks& inks, const Eigen::MatrixX2d& x, const std::vector<float>& closure,
                  const Eigen::VectorXd& weights, double pixelsPerUnit);

}  // namespace ib::render
