// Scene to multimesh in one call, for front ends: the multimesh `inbetween mesh` cached beside the
// scene when it is still current, a given .ibmesh file, or a fresh build (trace, map, Comesh
// Optimization, stiffness painted again). Thin on purpose: a front end that includes this header
// sees neither OpenMesh, OpenMP, the factorization nor a JSON library.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ib {

class Multimesh;      // multimesh/multimesh.h
struct Scene;         // scene/scene.h
struct KeyShape;      // meshing/key_shape.h
struct ComeshOptions; // comesh/comesh.h
struct ComeshReport;  // comesh/comesh.h
class TraceCache;     // meshing/trace_cache.h
struct PreviousMap;   // meshing/previous_map.h

struct SceneMultimeshOptions {
  // A .ibmesh file to use instead of the cache or a build; its key count must be the scene's.
  // Default empty: none.
  std::string meshFile;
  // Use the cache beside the scene (cachedMeshPath) when it is current: newer than the scene file,
  // every drawing and the stiffness image, and of the scene's key count. Default true.
  bool useCache = true;
  // When building: run Comesh Optimization on the initial map, then paint the stiffness again.
  // Default true.
  bool comesh = true;
  // Comesh Optimization's settings, read during the call; its progress callback is called too.
  // Default null: ComeshOptions' defaults.
  const ComeshOptions* comeshOptions = nullptr;
  // When building: the most threads (untangling, Comesh); 0 = all cores. Fewer run while other
  // programs keep cores busy (core/thread_budget.h). Default 0.
  int threads = 0;
  // When building: drawings traced by earlier builds, reused while unchanged (an editor's
  // rebuilds); used by one build at a time. Default null: every drawing is traced.
  TraceCache* traceCache = nullptr;
  // When building: the map of an earlier build to start each key's mapping from
  // (MultimeshBuildOptions::previous: for previews only). Default null.
  const PreviousMap* previous = nullptr;
};

// Where the multimesh came from.
enum class MeshSource {
  kCache,  // the current cache beside the scene
  kFile,   // SceneMultimeshOptions::meshFile
  kBuilt,  // built now from the drawings
};

struct SceneMultimesh {
  SceneMultimesh();
  ~SceneMultimesh();
  SceneMultimesh(SceneMultimesh&&) noexcept;
  SceneMultimesh& operator=(SceneMultimesh&&) noexcept;

  // The multimesh to play: the loaded one, or the built one (optimized when Comesh ran, else the
  // initial map). Never null.
  std::shared_ptr<const Multimesh> multimesh;
  // Built: the initial map before Comesh (the same object as `multimesh` when Comesh did not run).
  // Null when loaded.
  std::shared_ptr<const Multimesh> initial;
  MeshSource source = MeshSource::kBuilt;
  std::string file;  // cache or file: the path loaded; empty when built

  // The build's report, empty (0, null) when loaded:
  std::vector<KeyShape> shapes;                  // [key]: its shape after features and cuts (for meshSvg)
  std::vector<std::array<int, 2>> drawingSizes;  // [key]: the drawing's width and height, px
  double edgeLength = 0;                         // px: the edge length the build finally used
  std::shared_ptr<const ComeshReport> comesh;    // Comesh Optimization's statistics when it ran

  // What was assumed about odd but accepted input, whatever the source: sceneNotes(scene); and,
  // when Comesh ran here, a key it left with a smallest angle under 10 degrees or a map with a
  // MIPS maximum above 20 that the initial map did not have, with what to do. Front ends print
  // them (`inbetween: note: ...`); the library never does.
  std::vector<std::string> notes;
};

// The notes for a scene, each naming the scene file: the loader's (Scene::notes, e.g. one key: a
// still), then keys whose drawings' canvases differ in size (read from the PNG headers; a drawing
// that cannot be read is left to the error that reading it gives).
std::vector<std::string> sceneNotes(const Scene& scene);

// stage: what is being done, e.g. "tracing arch"; fraction: of the whole call, in [0, 1],
// non-decreasing from call to call, 1 on the last call.
using PipelineProgress = std::function<void(const std::string& stage, double fraction)>;

// The scene's multimesh, from the first of: options.meshFile, the current cache, a build. The
// cache lives at cachedMeshPath(scene.file); a cache that cannot be read or is out of date is
// rebuilt, not an error (and not rewritten: `inbetween mesh` writes it). Throws InputError for a
// missing or corrupt meshFile, for one whose key count is not the scene's (naming both files), and
// for whatever the build finds wrong with the scene (meshing/multimesh_builder.h).
SceneMultimesh sceneMultimesh(const Scene& scene, const SceneMultimeshOptions& options,
                              const PipelineProgress& progress = nullptr);

// The note of a build that had to refine its mesh to map every key (SceneMultimesh::notes): the
// scene file's name, the edge length it was built at (px) and each failed attempt, e.g.
// `at 6 px, key "sprout" folded near (265.0, 445.9)`, with what to set to skip them.
std::string refinementNote(const std::string& sceneFile, double edgeLength, const std::vector<std::string>& failedAttempts);

// The cache beside a scene file: SCENE's folder / SCENE's name .ibmesh, what `inbetween mesh` writes.
std::string cachedMeshPath(const std::string& scenePath);

// Vertices at the scene's features: for every key's feature, the boundary vertex of that key
// nearest to it; for every key's interior feature, the vertex of that key nearest to it (the
// build puts one exactly there). Sorted, without repeats.
std::vector<int> featureVertices(const Scene& scene, const Multimesh& mesh);

}  // namespace ib
