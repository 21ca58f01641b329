#include "scene_mesh.h"

#include "comesh/comesh.h"
#include "core/error.h"
#include "meshing/multimesh_builder.h"
#include "meshing/stiffness_paint.h"
#include "multimesh/multimesh_io.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace ib {

namespace fs = std::filesystem;

std::string cachedMeshPath(const std::string& scenePath) {
  const fs::path scene(scenePath);
  return (scene.parent_path() / scene.stem()).string() + ".ibmesh";
}

namespace {

bool cacheIsCurrent(const Scene& scene, const std::string& scenePath, const fs::path& cache) {
  std::error_code error;
  const auto cacheTime = fs::last_write_time(cache, error);
  if (error) return false;
  std::vector<std::string> inputs{scenePath};
  for (const KeySpec& key : scene.keys) inputs.push_back(key.drawing);
  for (const std::string& input : inputs) {
    const auto inputTime = fs::last_write_time(input, error);
    if (error || inputTime > cacheTime) return false;
  }
  return true;
}

}  // namespace

Multimesh buildSceneMultimesh(const Scene& scene, bool comesh, cli::Progress& progress, const std::string& label,
                              double progressShare) {
  MultimeshBuildOptions build;
  const double buildShare = (comesh ? 0.3 : 1.0) * progressShare;
  build.progress = [&](const std::string& stage, double fraction) { progress.update(label + stage, buildShare * fraction); };
  const BuiltScene built = buildMultimesh(scene, build);
  if (!comesh) return *built.multimesh;
  ComeshOptions options;
  options.progress = [&](int outer, double) {
    progress.update(label + "comesh, outer iteration " + std::to_string(outer),
                    buildShare + (progressShare - buildShare) * outer / options.outerIterations);
  };
  Multimesh mesh = comeshOptimize(*built.multimesh, &built.boundary, options, nullptr);
  paintStiffness(mesh, scene.stiffness, scene.solver.kappa);
  return mesh;
}

Multimesh sceneMultimesh(const Scene& scene, const std::string& scenePath, const SceneMeshOptions& options,
                         cli::Progress& progress, std::string* source) {
  const int keys = static_cast<int>(scene.keys.size());
  if (!options.meshFile.empty()) {
    Multimesh mesh = loadMultimesh(options.meshFile);
    if (mesh.keyCount() != keys)
      throw InputError(options.meshFile + ": has " + std::to_string(mesh.keyCount()) + " keys but " + scenePath + " has " +
                       std::to_string(keys));
    if (source) *source = options.meshFile;
    return mesh;
  }
  const std::string cache = cachedMeshPath(scenePath);
  if (cacheIsCurrent(scene, scenePath, cache)) {
    try {
      Multimesh mesh = loadMultimesh(cache);
      if (mesh.keyCount() == keys) {
        if (source) *source = cache;
        return mesh;
      }
    } catch (const InputError&) {  // a broken cache is rebuilt, not an error
    }
  }
  if (source) *source = options.comesh ? "built (with Comesh Optimization)" : "built (initial map)";
  return buildSceneMultimesh(scene, options.comesh, progress, "", options.progressShare);
}

std::vector<int> featureVertices(const Scene& scene, const Multimesh& mesh) {
  std::vector<int> out;
  for (int k = 0; k < static_cast<int>(scene.keys.size()) && k < mesh.keyCount(); ++k) {
    const Eigen::MatrixX2d X = mesh.keyPositions(k);
    for (const auto& [name, point] : scene.keys[k].features) {
      int best = -1;
      double bestDistance = std::numeric_limits<double>::infinity();
      for (int v : mesh.boundaryVertices(k)) {
        const double d = (X.row(v).transpose() - point).squaredNorm();
        if (d < bestDistance) {
          bestDistance = d;
          best = v;
        }
      }
      if (best >= 0) out.push_back(best);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace ib
