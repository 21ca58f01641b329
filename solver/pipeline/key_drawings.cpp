#include "pipeline/key_drawings.h"

#include "core/error.h"
#include "scene/scene.h"

#include <filesystem>

namespace ib {

std::vector<RgbaImage> readKeyDrawings(const Scene& scene) {
  std::vector<RgbaImage> out;
  for (const KeySpec& key : scene.keys) {
    try {
      out.push_back(readPng(key.drawing));
    } catch (const InputError& e) {
      throw InputError(std::filesystem::path(scene.file).filename().string() + ": key " + inQuotes(key.name) +
                       ": drawing " + e.what());
    }
  }
  return out;
}

}  // namespace ib
