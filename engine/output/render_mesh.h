// What the renderer draws: the multimesh's topology, each key's UVs (its positions over its
// drawing's size) and artwork, and the overlay geometry (edges, cohesive edges, features); plus
// one frame's request (positions, weights, view, overlays, onion skins, sampling).
#pragma once

#include "core/png_image.h"
#include "multimesh/multimesh.h"
#include "output/cut_ink.h"
#include "output/key_rim.h"
#include "output/silhouette_artwork.h"
#include "output/texture_levels.h"

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

namespace ib::render {

using Edge = ib::Edge;

// The cuts of a multimesh: the cohesive pairs of all keys, and the vertex pairs they collocate.
struct CutSides {
  std::vector<CohesivePair> pairs;  // every key's C_i, each pair once
  std::vector<int> pairOfTerm;      // [term]: index into pairs of each key's pair, in the solver's
                                    // order (key 0's pairs C_0, then C_1, ...: heldPairs)
  std::vector<Edge> partners;       // {a, c} and {b, d} of every pair where the two differ, each once
  std::vector<std::array<int, 2>> pairPartners;  // [pair]: indices into partners of its {a, c} and
                                                 // {b, d}, -1 where the two are one vertex
  std::vector<Edge> ring;           // {v, u}: v off the cuts shares a triangle with u on one
};

struct RenderMesh {
  int vertexCount = 0;
  std::vector<Triangle> triangles;               // t x 3 vertex indices (drawn without culling)
  std::vector<Eigen::MatrixX2f> keyUV;           // [key]: n x 2, key positions / drawing size, in [0, 1]
  std::vector<RgbaImage> artwork;                // [key]: the drawing as textured, straight alpha,
                                                 // its band along the mesh boundary as opaque as
                                                 // its interior (silhouette_artwork.h)
  std::vector<RgbaImage> drawings;               // [key]: the drawing as drawn, straight alpha, shown
                                                 // at and near the key (key_rim.h)
  KeyRim rim;                                    // triangles outside the boundary carrying the drawings' edges
  std::vector<Eigen::MatrixX2f> rimUV;           // [key]: rim points in key positions / drawing size
  std::vector<Edge> edges;                       // every mesh edge once (wireframe)
  std::vector<std::vector<Edge>> cohesiveEdges;  // [key]: both edges of each of C_i's pairs
  CutSides cutSides;                             // every key's cohesive pairs, for weldCuts
  CutInks inks;                                  // the drawings' outline ink, drawn where cuts open
  std::vector<int> features;                     // vertices marked as features
  // The artwork as the GPU samples it (textureLevels(textureLayers(mesh))), when made beforehand,
  // e.g. off a window's thread; null: the renderer makes it when it uploads.
  std::shared_ptr<const TextureLevels> texture;
};

// The render mesh of a multimesh whose key positions are in the pixels of `artwork[key]` (the
// drawings, straight alpha; their silhouette bands are made opaque with `silhouette`).
// `features` are vertex indices (may be empty). Throws std::invalid_argument when the artwork count
// does not match the keys, an image is empty or a feature is not a vertex.
RenderMesh renderMeshOf(const Multimesh& mesh, std::vector<RgbaImage> artwork, std::vector<int> features = {},
                        const SilhouetteOptions& silhouette = {});

// The texture's layers: `artwork` (keys 0..m-1), then `drawings` (layers m..2m-1).
std::vector<RgbaImage> textureLayers(const RenderMesh& mesh);

// Where the solver glues a cut, its two sides lie within a small fraction of a pixel of each other,
// and the keys that draw the cut open have antialiased, partly transparent texels along it. Drawn
// as they are, both would show as a hairline across a shape that is whole: MSAA samples falling
// in the sliver between the sides, and the open keys' alpha blended in. weldCuts closes gaps
// narrower than a pixel and says, per vertex, how closed its cut is, so that the artwork shader
// takes the opacity across it from the keys that draw it whole (shaders/artwork.frag).
// Distances are in target pixels, so a gap the picture can show is never welded shut, at any zoom.
struct CutWeldOptions {
  double glued = 0.5;  // target pixels: cut partners at most this far apart are welded (closure 1)
  double open = 1.5;   // target pixels: partners this far apart or more are left alone (closure 0)
};

struct CutWeld {
  Eigen::MatrixX2d positions;  // n x 2, in x's units: x with glued partners moved together
  std::vector<float> closure;  // n: 1 where a vertex's cut is glued, 0 away from cuts and where it is open
};

// A pair's closure is c = clamp((open - d) / (open - glued), 0, 1), where d is the larger of its
// two end gaps |x_a - x_c| and |x_b - x_d|, or 1 where the solver says the pair holds (`heldPairs`,
// optional: InterpolationResult::heldPairs of x, one flag per term of CutSides::pairOfTerm; a pair
// of several keys holds if any of its terms does): a held pair is glued by definition, even where
// it has stretched to a pixel or more just before it lets go. A vertex's closure is the largest
// of its pairs' (so the tip of a cut, where a == c, gets its pair's), and a vertex next to a cut
// takes the largest of its neighbours' on it: the triangles along a glued cut have closure 1
// throughout (an open key's partly transparent texels can reach a few pixels into them where its
// map stretches), and it falls to 0 across the next ring of triangles. Welding: each partner pair
// {u, v} has c_uv from its own gap (1 where a held pair collocates them), and u moves to
// u + sum_v c_uv (v - u) / (1 + sum_v c_uv): a glued pair meets at its midpoint, a glued group of
// mutual partners at its centroid, and a lone pair between the thresholds narrows continuously
// to d (1 - c) / (1 + c), which still grows with d.
// x (n x 2) is in drawing pixels, shown at `pixelsPerUnit` target pixels per drawing pixel (> 0).
// Throws std::invalid_argument unless 0 <= glued < open and heldPairs, if given, has one flag per
// term (and cutSides are renderMeshOf's, with pairOfTerm and pairPartners).
CutWeld weldCuts(const Eigen::MatrixX2d& x, const CutSides& cutSides, double pixelsPerUnit,
                   const CutWeldOptions& options = {}, const std::vector<char>* heldPairs = nullptr);

// The rectangle of drawing pixels shown on the target, x0 < x1 and y0 < y1 (y down).
struct ViewBox {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};

// `bounds` grown by `margin` (a fraction of its larger side) on every side, then widened or
// heightened about its centre to the target's aspect ratio, so shapes are not distorted.
ViewBox fitView(const ViewBox& bounds, int width, int height, double margin = 0.05);

// Bounding box of point sets (n x 2 each); throws std::invalid_argument when all are empty.
ViewBox boundsOf(const std::vector<Eigen::MatrixX2d>& points);

// A neighbouring frame drawn faded behind the current one (onion skin).
struct OnionSkin {
  const Eigen::MatrixX2d* positions = nullptr;  // n x 2, drawing pixels
  Eigen::VectorXd weights;                      // its interpolation weights (m)
  std::array<float, 3> tint{1, 1, 1};          // multiplies its colours
  float opacity = 0.3f;                         // in [0, 1]
  const std::vector<char>* heldPairs = nullptr;   // optional: which cohesive pairs hold (weldCuts)
};

struct Overlays {
  bool wireframe = false;  // every mesh edge, dark and translucent
  bool cohesive = false;   // cohesive edges of the keys with weight > 0, red
  bool features = false;   // feature vertices as blue squares
  float featureSize = 6;   // target pixels: side of a feature's square
};

// How the drawings' texels are filtered. kLinear: trilinear, over the mip chain (line art smooth at
// any size). kNearest: the nearest texel of the nearest mip level, so magnified pixel art keeps hard
// pixel edges (at 1:1 and larger every pixel is one texel of the drawing).
enum class Sampling { kLinear, kNearest };

struct FrameDraw {
  const Eigen::MatrixX2d* positions = nullptr;  // n x 2: current positions x, drawing pixels
  Eigen::VectorXd weights;                      // m convex weights; keys with weight 0 are not drawn
  const std::vector<char>* heldPairs = nullptr;   // optional: which cohesive pairs hold (weldCuts)
  ViewBox view;                                 // what part of the drawing plane the target shows
  Overlays overlays;
  std::vector<OnionSkin> onion;                 // at most kMaxOnionSkins, drawn first
  Sampling sampling = Sampling::kLinear;        // how the drawings' texels are filtered (onion skins too)
};

constexpr int kMaxOnionSkins = 4;
constexpr int kMaxActiveKeys = 8;  // blended per pixel; beyond that the 8 largest weights, renormalized

}  // namespace ib::render
