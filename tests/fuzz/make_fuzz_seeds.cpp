// Writes the fuzz targets' seed corpora from the bundled examples:
//   make_fuzz_seeds ASSETS_DIR OUT_DIR
// OUT_DIR/scene/ and OUT_DIR/scene_document/: every scene.json; OUT_DIR/png_tracing/: every drawing scaled down to at most
// 96 px on its long side (nearest pixel, so line work and alpha stay crisp); OUT_DIR/multimesh/:
// the initial multimesh of every scene whose file stays under 64 KiB, behind the target's mode
// byte (0: the checksum as stored); OUT_DIR/gltf_writer/: a few fixed byte strings.
#include "core/png_image.h"
#include "meshing/multimesh_builder.h"
#include "multimesh/multimesh_io.h"
#include "scene/scene.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

ib::RgbaImage scaledDown(const ib::RgbaImage& image, int longSide) {
  const double scale = std::min(1.0, static_cast<double>(longSide) / std::max(image.width, image.height));
  ib::RgbaImage out;
  out.width = std::max(1, static_cast<int>(image.width * scale));
  out.height = std::max(1, static_cast<int>(image.height * scale));
  out.hasAlpha = image.hasAlpha;
  out.pixels.resize(static_cast<size_t>(4 * out.width * out.height));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      std::copy_n(image.at(std::min(image.width - 1, static_cast<int>(x / scale)), std::min(image.height - 1, static_cast<int>(y / scale))),
                  4, out.at(x, y));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_fuzz_seeds ASSETS_DIR OUT_DIR\n");
    return 2;
  }
  const fs::path assets = argv[1], out = argv[2];
  int scenes = 0, drawings = 0, meshes = 0;
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(assets))
    if (fs::exists(entry.path() / "scene.json")) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) {
    const std::string name = folder.filename().string();
    std::ifstream in(folder / "scene.json", std::ios::binary);
    const std::string sceneText(std::istreambuf_iterator<char>(in), {});
    write(out / "scene" / (name + ".json"), sceneText);
    write(out / "scene_document" / (name + ".json"), sceneText);
    ++scenes;
    try {
      const ib::Scene scene = ib::loadScene((folder / "scene.json").string());
      for (size_t k = 0; k < scene.keys.size(); ++k) {
        write(out / "png_tracing" / (name + "-" + std::to_string(k) + ".png"), ib::encodePng(scaledDown(ib::readPng(scene.keys[k].drawing), 96)));
        ++drawings;
      }
      const ib::BuiltScene built = ib::buildMultimesh(scene, ib::MultimeshBuildOptions{});
      const std::string bytes = ib::encodeMultimesh(*built.multimesh);
      if (bytes.size() < 64 * 1024) {
        write(out / "multimesh" / (name + ".ibmesh"), std::string(1, '\0') + bytes);
        ++meshes;
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "make_fuzz_seeds: %s: %s\n", name.c_str(), e.what());
      return 1;
    }
  }
  std::mt19937 random(7);
  for (int i = 0; i < 8; ++i) {
    std::string bytes(64 + 32 * i, '\0');
    for (char& c : bytes) c = static_cast<char>(random());
    write(out / "gltf_writer" / ("seed-" + std::to_string(i)), bytes);
  }
  std::printf("make_fuzz_seeds: %d scenes, %d drawings, %d multimeshes, 8 glTF writer inputs in %s\n", scenes, drawings,
              meshes, out.string().c_str());
  return 0;
}
