// The multimesh a front end plays: the one `inbetween mesh` cached beside the scene when it is
// still current, a given file, or a fresh build (with Comesh Optimization by default).
#pragma once

#include "multimesh/multimesh.h"
#include "progress.h"
#include "scene/scene.h"

#include <string>

namespace ib {

struct SceneMeshOptions {
  std::string meshFile;   // a .ibmesh to use; empty = the cache beside the scene when current, else build
  bool comesh = true;     // when building: run Comesh Optimization (and repaint stiffness). Default on
  double progressShare = 1;  // fraction of the command's progress bar the build takes, in (0, 1]
};

// The scene's cache file: SCENE's folder / SCENE's name .ibmesh (what `inbetween mesh` writes).
std::string cachedMeshPath(const std::string& scenePath);

// Loads or builds the multimesh. A cache is current when it is newer than the scene file and every
// drawing and has the scene's key count. Describes where it came from in `source`. Throws
// InputError for a missing or corrupt --mesh file, or one whose key count differs from the scene's.
Multimesh sceneMultimesh(const Scene& scene, const std::string& scenePath, const SceneMeshOptions& options,
                         cli::Progress& progress, std::string* source = nullptr);

// Builds the multimesh: trace, map, then Comesh Optimization and stiffness painting when `comesh`.
Multimesh buildSceneMultimesh(const Scene& scene, bool comesh, cli::Progress& progress, const std::string& label,
                              double progressShare);

// Vertices at the scene's features: for every key's feature, the boundary vertex of that key
// nearest to it. Sorted, without repeats.
std::vector<int> featureVertices(const Scene& scene, const Multimesh& mesh);

}  // namespace ib
