// The glTF document of a baked animation (internal to the exporter: it shows tinygltf). One mesh
// with one primitive per key drawing that appears (a layer, bottom to top in key order), all
// sharing the base positions, the indices and the morph targets (one per kept frame but the
// first, which is the base); a `weights` animation that keeps at most two targets active; the
// layers' cross-fade as animated alpha factors through KHR_animation_pointer; and the ink on
// opened cuts in a node of its own (ink_node.h). docs/export.md.
#pragma once

#include "export/baked_animation.h"
#include "export/position_codec.h"
#include "output/render_mesh.h"

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace ib::gltf {

// How a bufferView's bytes may be compressed (EXT_meshopt_compression): vertex-like elements of
// `stride` bytes, or a triangle list of `stride`-byte indices; kNone for images.
struct ViewCodec {
  enum class Kind { kNone, kAttributes, kTriangles };
  Kind kind = Kind::kNone;
  int stride = 0;  // bytes per element (a multiple of 4 for attributes; 2 or 4 for indices)
  int count = 0;   // elements (vertices, keyframes or indices)
};

struct GltfDocument {
  tinygltf::Model model;           // every object but the buffers (written by gltf_file)
  std::vector<unsigned char> bin;  // buffer 0: every bufferView's bytes, 4-byte aligned
  std::vector<ViewCodec> views;    // [bufferView]: how it may be compressed
  size_t fallbackBytes = 0;        // > 0: buffer 1 is a meshopt fallback buffer of this length, without data
};

struct DocumentInput {
  const BakedAnimation* baked = nullptr;
  const render::RenderMesh* mesh = nullptr;
  const PositionCodec* codec = nullptr;      // the base is baked->positions[kept.front()]
  std::vector<int> kept;                     // frames with a morph target (reduceFrames), first = base
  std::vector<std::string> keyNames;         // [key], for the materials' names
  std::string name;                          // the node's, the mesh's and the animation's
  std::array<int, 2> canvas{1, 1};           // drawing pixels
  double pixelsPerUnit = 100;
  bool nearest = false;                      // NEAREST texture filtering (pixel art), else trilinear
};

GltfDocument buildDocument(const DocumentInput& input);

// The layers' alpha factors at interpolation weights w (m x 1): drawn bottom to top in key order
// over one another, layer k at w_k / (w_0 + .. + w_k) gives every opaque key the weight w_k.
std::vector<double> layerAlphas(const Eigen::VectorXd& w);

}  // namespace ib::gltf
