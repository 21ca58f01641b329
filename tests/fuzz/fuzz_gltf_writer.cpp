// libFuzzer target: the glTF writer's input (writeGltf): a baked animation of any frame count
// whose positions and weights may be NaN, infinite or huge, frame times out of order, key names
// of any bytes, any canvas and pixels per unit, quantization, meshopt and frame dropping on or
// off, over a small multimesh of 1 to 3 keys. Bad input must come back as InputError or
// std::invalid_argument (gltf_export.h); the file is written to a scratch folder.
#include "core/error.h"
#include "export/gltf_export.h"
#include "multimesh/multimesh.h"
#include "output/render_mesh.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace {

double anyNumber(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 7)) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return -std::numeric_limits<double>::infinity();
    case 3: return in.ConsumeFloatingPoint<double>();  // any finite double, huge ones included
    default: return in.ConsumeFloatingPointInRange<double>(-100, 300);
  }
}

ib::Multimesh squareMesh(int keys, FuzzedDataProvider& in) {
  // 3 x 3 grid of vertices, 8 triangles; each key a scaled, shifted copy (always valid).
  std::vector<ib::Triangle> triangles;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      const int v = 3 * y + x;
      triangles.push_back({v, v + 1, v + 4});
      triangles.push_back({v, v + 4, v + 3});
    }
  ib::Multimesh mesh(9, triangles);
  for (int k = 0; k < keys; ++k) {
    const double size = in.ConsumeFloatingPointInRange<double>(1, 200);
    Eigen::MatrixX2d x(9, 2);
    for (int v = 0; v < 9; ++v) x.row(v) << 10 + size * (v % 3), 10 + size * (v / 3);
    mesh.addKey(x, {}, {0, 1, 2, 5, 8, 7, 6, 3});
  }
  return mesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  const int keys = in.ConsumeIntegralInRange<int>(1, 3);
  const ib::Multimesh mesh = squareMesh(keys, in);
  std::vector<ib::RgbaImage> artwork;
  for (int k = 0; k < keys; ++k) {
    ib::RgbaImage image;
    image.width = in.ConsumeIntegralInRange<int>(1, 16);
    image.height = in.ConsumeIntegralInRange<int>(1, 16);
    image.hasAlpha = in.ConsumeBool();
    image.pixels = in.ConsumeBytes<uint8_t>(static_cast<size_t>(4 * image.width * image.height));
    image.pixels.resize(static_cast<size_t>(4 * image.width * image.height), 255);
    artwork.push_back(std::move(image));
  }
  const ib::render::RenderMesh renderMesh = ib::render::renderMeshOf(mesh, artwork);

  ib::gltf::BakedAnimation baked;
  const int frames = in.ConsumeIntegralInRange<int>(0, 12);
  const int first = in.ConsumeIntegralInRange<int>(-3, 100);
  baked.fps = anyNumber(in);
  baked.loops = in.ConsumeBool();
  baked.shapeSize = anyNumber(in);
  const bool wellFormed = in.ConsumeBool();  // else the arrays' sizes disagree as well
  for (int f = 0; f < frames; ++f) {
    baked.frames.push_back(first + f);
    baked.times.push_back(in.ConsumeBool() ? anyNumber(in) : f / 24.0);
    Eigen::MatrixX2d x = mesh.keyPositions(f % keys);
    const int broken = in.ConsumeIntegralInRange<int>(0, 3);
    for (int b = 0; b < broken; ++b) x(in.ConsumeIntegralInRange<int>(0, 8), in.ConsumeIntegralInRange<int>(0, 1)) = anyNumber(in);
    baked.positions.push_back(wellFormed || f % 2 ? x : Eigen::MatrixX2d(in.ConsumeIntegralInRange<int>(0, 12), 2));
    Eigen::VectorXd w = Eigen::VectorXd::Zero(wellFormed ? keys : in.ConsumeIntegralInRange<int>(0, 4));
    for (int k = 0; k < w.size(); ++k) w[k] = in.ConsumeBool() ? anyNumber(in) : in.ConsumeProbability<double>();
    baked.weights.push_back(w);
  }
  ib::gltf::ExportedScene scene;
  scene.name = in.ConsumeRandomLengthString(64);
  for (int k = 0; k < keys; ++k) scene.keyNames.push_back(in.ConsumeRandomLengthString(32));
  scene.canvas = {in.ConsumeIntegralInRange<int>(-2, 5000), in.ConsumeIntegralInRange<int>(-2, 5000)};
  ib::gltf::GltfExportOptions options;
  options.pixelsPerUnit = in.ConsumeBool() ? anyNumber(in) : 100;
  options.maxError = in.ConsumeBool() ? anyNumber(in) : 0;
  options.quantize = in.ConsumeBool();
  options.meshopt = in.ConsumeBool();
  options.sampling = in.ConsumeBool() ? ib::render::Sampling::kNearest : ib::render::Sampling::kLinear;

  static const std::string folder = [] {
    const auto dir = std::filesystem::temp_directory_path() / ("inbetween-fuzz-gltf-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return dir.string();
  }();
  const std::string path = folder + (in.ConsumeBool() ? "/out.glb" : "/out.gltf");
  try {
    (void)ib::gltf::writeGltf(baked, renderMesh, scene, options, path);
  } catch (const ib::InputError&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
