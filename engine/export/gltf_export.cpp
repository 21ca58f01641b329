#include "export/gltf_export.h"

#include "core/error.h"
#include "export/frame_reduction.h"
#include "export/gltf_document.h"
#include "export/gltf_file.h"
#include "export/meshopt_compression.h"
#include "export/position_codec.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace ib::gltf {

namespace {

DocumentInput inputFor(const BakedAnimation& baked, const render::RenderMesh& mesh, const ExportedScene& scene,
                       const GltfExportOptions& options, const PositionCodec& codec, std::vector<int> kept) {
  DocumentInput in;
  in.baked = &baked;
  in.mesh = &mesh;
  in.codec = &codec;
  in.kept = std::move(kept);
  in.keyNames = scene.keyNames;
  in.name = scene.name;
  in.canvas = scene.canvas;
  in.pixelsPerUnit = options.pixelsPerUnit;
  in.nearest = options.sampling == render::Sampling::kNearest;
  return in;
}

// The baked animation is one the writer can store: a time, positions (n x 2, finite) and weights
// (one per key, >= 0, not all 0) for every frame, times finite and not decreasing, a positive frame rate.
// A caller's mistake, not the user's (found by the fuzz target: mismatched sizes read past arrays).
void checkBaked(const BakedAnimation& baked, const render::RenderMesh& mesh) {
  const size_t frames = baked.frames.size();
  if (baked.times.size() != frames || baked.positions.size() != frames || baked.weights.size() != frames)
    throw std::invalid_argument("writeGltf: the baked frames, times, positions and weights differ in count");
  if (!(baked.fps > 0) || !std::isfinite(baked.fps)) throw std::invalid_argument("writeGltf: fps must be positive");
  if (!(baked.shapeSize > 0) || !std::isfinite(baked.shapeSize)) throw std::invalid_argument("writeGltf: shapeSize must be positive");
  for (size_t f = 0; f < frames; ++f) {
    const std::string frame = "writeGltf: frame " + std::to_string(f) + ": ";
    if (baked.positions[f].rows() != mesh.vertexCount || !baked.positions[f].allFinite())
      throw std::invalid_argument(frame + "positions must be finite, one row per vertex");
    if (!baked.closure.empty() && (baked.closure.size() != frames || baked.closure[f].size() != static_cast<size_t>(mesh.vertexCount)))
      throw std::invalid_argument(frame + "closure must be empty or one value per vertex in every frame");
    const Eigen::VectorXd& w = baked.weights[f];
    if (w.size() != static_cast<Eigen::Index>(mesh.artwork.size()) || !w.allFinite() || w.minCoeff() < 0 || !(w.sum() > 0))
      throw std::invalid_argument(frame + "weights must be one per key, finite, >= 0 and not all 0");
    if (!std::isfinite(baked.times[f]) || (f > 0 && baked.times[f] < baked.times[f - 1]))
      throw std::invalid_argument(frame + "times must be finite and not decreasing");
  }
}

}  // namespace

void checkGltfPath(const std::string& path, const std::string& field) { containerOf(path, field); }

GltfExportReport writeGltf(const BakedAnimation& baked, const render::RenderMesh& mesh, const ExportedScene& scene,
                           const GltfExportOptions& options, const std::string& path) {
  if (!(options.pixelsPerUnit > 0) || !std::isfinite(options.pixelsPerUnit))
    throw std::invalid_argument("writeGltf: pixelsPerUnit must be positive");
  if (!(options.maxError >= 0) || !std::isfinite(options.maxError))
    throw std::invalid_argument("writeGltf: maxError must be >= 0");
  if (baked.frames.empty()) throw std::invalid_argument("writeGltf: no frames baked");
  checkBaked(baked, mesh);
  if (static_cast<int>(scene.keyNames.size()) != static_cast<int>(mesh.artwork.size()))
    throw std::invalid_argument("writeGltf: one key name per drawing");
  const Container container = containerOf(path, "-o");
  const std::string binName = std::filesystem::path(path).replace_extension(".bin").filename().string();
  const bool quantize = options.quantize || options.meshopt;
  const int n = static_cast<int>(baked.frames.size());

  const PositionCodec codec(scene.canvas, options.pixelsPerUnit, quantize, baked.positions.front(), baked.positions);
  const FrameReduction reduction = reduceFrames(
      baked.positions, [&](int f) { return codec.decoded(baked.positions[f]); }, baked.times, options.maxError);
  if (options.maxError > 0 && reduction.maxError > options.maxError) {
    char message[200];
    std::snprintf(message, sizeof message,
                  "--max-error %g: the decoded positions alone are %.3g drawing pixels off (16-bit quantization); "
                  "ask for at least that",
                  options.maxError, reduction.maxError);
    throw InputError(message);
  }
  GltfDocument doc = buildDocument(inputFor(baked, mesh, scene, options, codec, reduction.kept));
  if (options.meshopt) compressWithMeshopt(doc);

  GltfExportReport report;
  report.frames = n;
  report.targets = static_cast<int>(reduction.kept.size()) - 1;
  report.layers = static_cast<int>(doc.model.meshes.front().primitives.size());
  report.maxError = reduction.maxError;
  report.shapeSize = baked.shapeSize;
  if (quantize || options.maxError > 0) {
    const PositionCodec raw(scene.canvas, options.pixelsPerUnit, false, baked.positions.front(), baked.positions);
    std::vector<int> every(n);
    for (int f = 0; f < n; ++f) every[f] = f;
    report.bytesRaw = documentBytes(buildDocument(inputFor(baked, mesh, scene, options, raw, every)), container, binName);
  }
  report.bytes = writeDocument(doc, path);
  if (report.bytesRaw == 0) report.bytesRaw = report.bytes;  // nothing reduced: the same file
  return report;
}

}  // namespace ib::gltf
