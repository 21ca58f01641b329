#include "export/export_job.h"

#include "core/error.h"
#include "export/baked_animation.h"
#include "multimesh/multimesh.h"
#include "output/render_mesh.h"

#include <algorithm>

namespace ib::gltf {

GltfExportReport exportAnimation(const Scene& scene, const Multimesh& mesh, std::vector<RgbaImage> drawings,
                                 const std::string& path, const ExportJobOptions& options, const JobProgress& progress) {
  const int frameCount = scene.timeline.frameCount();
  const int first = options.frames[0], last = options.frames[1];
  if (first < 0 || first > last || last >= frameCount)
    throw InputError("frames " + std::to_string(first) + ".." + std::to_string(last) + " are not in the timeline's 0.." +
                     std::to_string(frameCount - 1));
  // Every frame a 32-bit float target of 12 bytes per vertex: refuse before solving what no glTF
  // container holds (frame dropping and meshopt shrink it only afterwards, by an amount unknown yet).
  const double targetBytes = 12.0 * mesh.vertexCount() * (last - first + 1);
  if (targetBytes > 3.5 * 1024 * 1024 * 1024)
    throw InputError("export: " + std::to_string(last - first + 1) + " frames of " + std::to_string(mesh.vertexCount()) +
                     " vertices would be " + std::to_string(static_cast<long long>(targetBytes / (1 << 20))) +
                     " MiB of morph targets, more than a glTF file holds: export fewer frames (--frames) or mesh coarser "
                     "(a larger \"edge_length\" in " + scene.file + ")");
  ExportedScene exported;
  exported.name = options.name;
  for (const KeySpec& key : scene.keys) exported.keyNames.push_back(key.name);
  for (const RgbaImage& d : drawings) {
    exported.canvas[0] = std::max(exported.canvas[0], d.width);
    exported.canvas[1] = std::max(exported.canvas[1], d.height);
  }
  render::RenderMesh renderMesh = render::renderMeshOf(mesh, std::move(drawings));
  if (!scene.cutInk) renderMesh.inks = {};
  FrameStream stream = sceneFrameStream(scene, mesh, options.solving);
  const BakedAnimation baked = bakeAnimation(stream, renderMesh.cutSides, options.frames, [&](int done, int total) {
    if (progress)
      progress("solving frame " + std::to_string(first + done - 1) + " (" + std::to_string(done) + " of " + std::to_string(total) + ")",
               0.9 * done / total);
  });
  if (progress) progress("writing " + path, 0.95);
  const GltfExportReport report = writeGltf(baked, renderMesh, exported, options.gltf, path);
  if (progress) progress("written", 1);
  return report;
}

}  // namespace ib::gltf
