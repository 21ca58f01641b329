// What the renderer draws: the multimesh's topology, each key's UVs (its positions over its
// drawing's size) and artwork, and the overlay geometry (edges, cohesive edges, features); plus
// one frame's request (positions, weights, view, overlays, onion skins).
#pragma once

#include "multimesh.h"
#include "png_image.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace ib::render {

using Edge = std::array<int, 2>;

struct RenderMesh {
  int vertexCount = 0;
  std::vector<Triangle> triangles;               // t x 3 vertex indices (drawn without culling)
  std::vector<Eigen::MatrixX2f> keyUV;           // [key]: n x 2, key positions / drawing size, in [0, 1]
  std::vector<RgbaImage> artwork;                // [key]: the drawing, straight alpha
  std::vector<Edge> edges;                       // every mesh edge once (wireframe)
  std::vector<std::vector<Edge>> cohesiveEdges;  // [key]: both edges of each of C_i's pairs
  std::vector<int> features;                     // vertices marked as features
};

// The render mesh of a multimesh whose key positions are in the pixels of `artwork[key]`.
// `features` are vertex indices (may be empty). Throws InputError when the artwork count does not
// match the keys or an image is empty.
RenderMesh renderMeshOf(const Multimesh& mesh, std::vector<RgbaImage> artwork, std::vector<int> features = {});

// The rectangle of drawing pixels shown on the target, x0 < x1 and y0 < y1 (y down).
struct ViewBox {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};

// `bounds` grown by `margin` (a fraction of its larger side) on every side, then widened or
// heightened about its centre to the target's aspect ratio, so shapes are not distorted.
ViewBox fitView(const ViewBox& bounds, int width, int height, double margin = 0.05);

// Bounding box of point sets (n x 2 each); throws InputError when all are empty.
ViewBox boundsOf(const std::vector<Eigen::MatrixX2d>& points);

// A neighbouring frame drawn faded behind the current one (onion skin).
struct OnionSkin {
  const Eigen::MatrixX2d* positions = nullptr;  // n x 2, drawing pixels
  Eigen::VectorXd weights;                      // its interpolation weights (m)
  std::array<float, 3> tint{1, 1, 1};          // multiplies its colours
  float opacity = 0.3f;                         // in [0, 1]
};

struct Overlays {
  bool wireframe = false;  // every mesh edge, dark and translucent
  bool cohesive = false;   // cohesive edges of the keys with weight > 0, red
  bool features = false;   // feature vertices as blue squares
  float featureSize = 6;   // target pixels: side of a feature's square
};

struct FrameDraw {
  const Eigen::MatrixX2d* positions = nullptr;  // n x 2: current positions x, drawing pixels
  Eigen::VectorXd weights;                      // m convex weights; keys with weight 0 are not drawn
  ViewBox view;                                 // what part of the drawing plane the target shows
  Overlays overlays;
  std::vector<OnionSkin> onion;                 // at most kMaxOnionSkins, drawn first
};

constexpr int kMaxOnionSkins = 4;
constexpr int kMaxActiveKeys = 8;  // blended per pixel; beyond that the 8 largest weights, renormalized

}  // namespace ib::render
