// `inbetween export`'s work as a job: a scene's frames solved in order (pipeline/scene_frames.h),
// welded and baked, then written as glTF (gltf_export.h). It reports progress and leaves the
// command line to the front end. CPU only.
#pragma once

#include "core/png_image.h"
#include "export/gltf_export.h"
#include "pipeline/scene_frames.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace ib::gltf {

struct ExportJobOptions {
  std::array<int, 2> frames{0, 0};  // first and last frame, inclusive, within the timeline
  GltfExportOptions gltf;           // scale, frame dropping, quantization, compression, sampling
  FrameOptions solving;             // how the frames are solved (threads, ...)
  std::string name;                 // the node's, mesh's and animation's name
};

// stage: what is being done, e.g. "solving frame 12 (13 of 48)"; fraction of the job in [0, 1].
using JobProgress = std::function<void(const std::string& stage, double fraction)>;

// Bakes `scene`'s frames on `mesh` (a multimesh of the scene) with the key drawings of the scene
// (pipeline/key_drawings.h) and writes them to `path` (.glb or .gltf). InputError for a frame
// range outside the timeline, for more morph-target data than a glTF file holds (refused before
// solving, saying what to do), and as writeGltf says.
GltfExportReport exportAnimation(const Scene& scene, const Multimesh& mesh, std::vector<RgbaImage> drawings,
                                 const std::string& path, const ExportJobOptions& options, const JobProgress& progress = nullptr);

}  // namespace ib::gltf
