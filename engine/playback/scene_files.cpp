#include "playback/scene_files.h"

#include "core/error.h"
#include "multimesh/multimesh_io.h"
#include "pipeline/scene_multimesh.h"
#include "scene/parameters.h"

#include <nlohmann/json.hpp>

namespace ib::play {

namespace fs = std::filesystem;

FileStamp stamp(const std::string& path) {
  FileStamp s;
  s.path = path;
  std::error_code error;
  s.time = fs::last_write_time(path, error);
  if (error) return s;
  s.size = fs::file_size(path, error);
  s.exists = !error;
  return s;
}

std::vector<FileStamp> stampAll(const std::vector<std::string>& paths) {
  std::vector<FileStamp> out;
  for (const std::string& path : paths) out.push_back(stamp(path));
  return out;
}

// The files a scene is made from: the scene file, every drawing, the stiffness image.
std::vector<std::string> sceneFiles(const Scene& scene) {
  std::vector<std::string> files{scene.file};
  for (const KeySpec& key : scene.keys) files.push_back(key.drawing);
  if (!scene.stiffness.image.empty()) files.push_back(scene.stiffness.image);
  return files;
}

// The files the multimesh is built from: every drawing and the stiffness image.
std::vector<std::string> meshFiles(const Scene& scene) {
  std::vector<std::string> files = sceneFiles(scene);
  files.erase(files.begin());
  return files;
}

// The scene file's fields that shape the multimesh, as canonical text: all but the timeline's
// marks and the parameters whose change does not invalidate the multimesh (scene/parameters.h:
// the solver's cohesive and non-overlap fields, the dynamics, sampling...; solver.kappa is painted
// into the mesh). Two scenes with the same text, over unchanged drawings, have the same
// multimesh, so saving tuned parameters reloads the scene without rebuilding it.
std::string meshFields(const std::string& sceneText) {
  nlohmann::json j = nlohmann::json::parse(sceneText, nullptr, false);
  if (!j.is_object()) return sceneText;
  j.erase("timeline");
  for (const ParameterSpec& spec : parameterTable()) {
    if (spec.field.empty() || spec.invalidates == Invalidates::kMultimesh) continue;
    const size_t dot = spec.field.find('.');
    if (dot == std::string::npos) {
      j.erase(spec.field);
      continue;
    }
    const std::string section = spec.field.substr(0, dot);
    if (!j.contains(section) || !j[section].is_object()) continue;
    j[section].erase(spec.field.substr(dot + 1));
    if (j[section].empty()) j.erase(section);  // saving may add it
  }
  return j.dump();  // keys sorted: the order in the file does not matter
}

// NAME.initial.ibmesh beside the scene (what `inbetween mesh` writes next to the cache) when it
// is at least as new as the scene's files and has the scene's key count; else null.
std::shared_ptr<const Multimesh> initialBeside(const Scene& scene) {
  const fs::path file = fs::path(cachedMeshPath(scene.file)).replace_extension(".initial.ibmesh");
  std::error_code error;
  const auto time = fs::last_write_time(file, error);
  if (error) return nullptr;
  for (const std::string& input : sceneFiles(scene)) {
    const auto inputTime = fs::last_write_time(input, error);
    if (error || inputTime > time) return nullptr;
  }
  try {
    auto mesh = std::make_shared<const Multimesh>(loadMultimesh(file.string()));
    if (mesh->keyCount() != static_cast<int>(scene.keys.size())) return nullptr;
    return mesh;
  } catch (const InputError&) {
    return nullptr;  // optional: a display aid, not worth failing the scene for
  }
}

}  // namespace ib::play
