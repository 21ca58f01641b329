// What the scene reloader (playback/scene_reloader.cpp) knows about a scene's files: their stamps
// (modification time and size) for poll(), which files a scene and its multimesh are made from,
// the scene text's fields that shape the multimesh, and the initial map `inbetween mesh` leaves
// beside a scene. Internal to the playback library.
#pragma once

#include "multimesh/multimesh.h"
#include "scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ib::play {

// What poll() compares: a file's modification time and size, or its absence.
struct FileStamp {
  std::string path;
  bool exists = false;
  std::filesystem::file_time_type time{};
  std::uintmax_t size = 0;

  bool operator==(const FileStamp& other) const {
    return path == other.path && exists == other.exists && time == other.time && size == other.size;
  }
};

FileStamp stamp(const std::string& path);
std::vector<FileStamp> stampAll(const std::vector<std::string>& paths);

// The files a scene is made from: the scene file, every drawing, the stiffness image.
std::vector<std::string> sceneFiles(const Scene& scene);
// The files the multimesh is built from: every drawing and the stiffness image.
std::vector<std::string> meshFiles(const Scene& scene);

// The scene file's fields that shape the multimesh, as canonical text: all but the timeline's
// marks and the parameters whose change does not invalidate the multimesh (scene/parameters.h).
// Two scenes with the same text, over unchanged drawings, have the same multimesh.
std::string meshFields(const std::string& sceneText);

// NAME.initial.ibmesh beside the scene (what `inbetween mesh` writes next to the cache) when it
// is at least as new as the scene's files and has the scene's key count; else null.
std::shared_ptr<const Multimesh> initialBeside(const Scene& scene);

}  // namespace ib::play
