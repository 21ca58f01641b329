// Scene to multimesh (docs/design.md, data flow "scene" and "multimesh"): trace every key's drawing,
// snap features, apply cuts, match boundaries, mesh the reference key and map the mesh onto every
// other key without foldovers.
#pragma once

#include "comesh/comesh_mesh.h"
#include "meshing/key_shape.h"
#include "meshing/previous_map.h"
#include "meshing/reference_mesh.h"
#include "meshing/untangle.h"
#include "multimesh/multimesh.h"
#include "scene/scene.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ib {

class TraceCache;

struct MultimeshBuildOptions {
  KeyShapeOptions shape;
  UntangleOptions untangle;
  // Attempts after the first when a key cannot be mapped without foldovers; each retry divides
  // the edge length by 1.5. Default 2.
  int refinements = 2;
  // Called with a stage name and the fraction done, for progress display. Optional.
  std::function<void(const std::string& stage, double fraction)> progress;
  // Traced drawings kept from earlier builds (meshing/trace_cache.h); null: every drawing is traced.
  TraceCache* traceCache = nullptr;
  // A map built before for these keys (meshing/previous_map.h): each key's map is where it puts
  // the new mesh's points (interior features where the key places them), untangled from there only
  // when that folds a triangle, instead of a Tutte embedding untangled; a key it does not cover, or
  // whose start does not untangle, is mapped as without it. Much faster after a small edit, but the map
  // then depends on the one before: for previews (the editor's quick rebuild), not for files.
  // Null: none (the default).
  const PreviousMap* previous = nullptr;
};

// What a built scene is made of, for pictures and checks.
struct KeyReport {
  std::string key;
  int cohesiveEdges = 0;   // pairs in C_i
  double smallestArea = 0; // px^2: smallest triangle area in this key
};

struct BuiltScene {
  std::vector<std::array<int, 2>> drawingSizes;  // [key]: width, height of the drawing in pixels
  std::vector<std::vector<Outline>> outlines;  // [key]: traced drawing
  std::vector<KeyShape> shapes;                // [key]: after features and cuts
  std::optional<Multimesh> multimesh;          // keys in scene order, positions in drawing pixels
  ComeshBoundary boundary;                     // the multimesh's boundary vertices on the keys' outlines
  std::vector<KeyReport> report;               // [key]
  double edgeLength = 0;                       // px: the edge length finally used
  int attempts = 0;                            // edge lengths tried with the corners that built (1 = no refinement needed)
  // Each coarser edge length that folded with the corners that built, e.g. `at 6 px, corners
  // "vertices", correspondence "outline", key "full" folded near (312.0, 140.0)`.
  std::vector<std::string> failedAttempts;
  // When the scene's corners or correspondence folded and the build got past it: what folded and
  // what was used instead (other corners, arc length, or no shape knots near a fold); empty otherwise.
  std::string fallback;
};

// Throws InputError naming the file, key and place for bad drawings, features, cuts, loops that do
// not match, and keys that cannot be mapped without foldovers even after refinement.
BuiltScene buildMultimesh(const Scene& scene, const MultimeshBuildOptions& options);

}  // namespace ib
