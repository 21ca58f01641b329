#include "pipeline/key_drawings.h"

#include "core/error.h"
#include "meshing/paper.h"
#include "meshing/trace_cache.h"
#include "scene/scene.h"

#include <filesystem>

namespace ib {

std::vector<RgbaImage> readKeyDrawings(const Scene& scene, TraceCache* traces) {
  std::vector<RgbaImage> out;
  for (const KeySpec& key : scene.keys) {
    try {
      RgbaImage image = traces ? traces->drawing(key.drawing) : readPng(key.drawing);
      // On paper: the paper transparent and its antialiased edge un-blended, as traced.
      if (tracedByColour(image, scene.tracing))
        image = paperToAlpha(image, findPaper(image, scene.tracing, key.holes, key.drawing));
      out.push_back(std::move(image));
    } catch (const InputError& e) {
      throw InputError(std::filesystem::path(scene.file).filename().string() + ": key " + inQuotes(key.name) +
                       ": drawing " + e.what());
    }
  }
  return out;
}

}  // namespace ib
