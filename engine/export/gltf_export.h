// glTF 2.0 export of a baked animation (`inbetween export`; docs/export.md): one mesh whose morph
// targets are the frames, a weights animation that keeps at most two targets active, one layer
// per key drawing cross-faded by animated alpha factors (KHR_animation_pointer), the drawings as
// embedded PNG textures, opened cuts' outline ink as strips in a second node. Optionally fewer
// frames (within a bound), 16-bit quantization and meshopt compression. CPU only; front ends
// include this header alone.
#pragma once

#include "export/baked_animation.h"
#include "output/render_mesh.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace ib::gltf {

struct GltfExportOptions {
  // Drawing pixels per glTF unit (metre). Default 100, as Unity's sprites and Spine's exports.
  double pixelsPerUnit = 100;
  // Drawing pixels: > 0 drops the frames a client rebuilds within this distance at every vertex
  // and every frame time (reduceFrames). Default 0: one morph target per frame.
  double maxError = 0;
  // Morph targets as 16-bit normalized deltas and UVs as 16-bit (KHR_mesh_quantization, then a
  // required extension). Default false: 32-bit floats, core glTF.
  bool quantize = false;
  // Buffers compressed with EXT_meshopt_compression (required extension; implies quantize).
  // Default false.
  bool meshopt = false;
  // Texture filtering: kNearest for pixel art (NEAREST_MIPMAP_NEAREST), else trilinear. Default linear.
  render::Sampling sampling = render::Sampling::kLinear;
};

struct GltfExportReport {
  int frames = 0;          // baked frames
  int targets = 0;         // morph targets written (kept frames but the base)
  int layers = 0;          // primitives: key drawings that appear
  size_t bytes = 0;        // the files written (.glb, or .gltf plus .bin)
  size_t bytesRaw = 0;     // the same animation with every frame, 32-bit floats, uncompressed
  double maxError = 0;     // drawing pixels: largest distance of a decoded vertex from the baked
                           // one, over every frame time (float rounding, quantization, dropping)
  double shapeSize = 1;    // drawing pixels: s = sqrt(mean key area), the unit of the solver's lengths
};

// What the exported file is made of, besides the baked frames.
struct ExportedScene {
  std::string name;                   // the node's, mesh's and animation's name
  std::vector<std::string> keyNames;  // [key]: the layers' materials' names
  std::array<int, 2> canvas{1, 1};    // drawing pixels: the largest drawing's size
};

// InputError naming `field` and the path unless it ends in .glb or .gltf (any case): for front
// ends to check before the long work.
void checkGltfPath(const std::string& path, const std::string& field);

// Writes `path` (.glb or .gltf + .bin, atomically). Throws InputError for a path of another
// extension or that cannot be written, and when the measured error exceeds options.maxError
// (a bound below the quantization step); std::invalid_argument for options out of range.
GltfExportReport writeGltf(const BakedAnimation& baked, const render::RenderMesh& mesh, const ExportedScene& scene,
                           const GltfExportOptions& options, const std::string& path);

}  // namespace ib::gltf
