// The glTF exporter's parts (engine/export) and its files read back by tinygltf's loader. The
// clients' checks (Khronos validator, three.js, Chromium) are in tests/clients.
#include "animation/frame_stream.h"
#include "core/error.h"
#include "export/baked_animation.h"
#include "export/frame_reduction.h"
#include "export/gltf_document.h"
#include "export/gltf_export.h"
#include "export/position_codec.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "output/render_mesh.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_frames.h"
#include "pipeline/scene_multimesh.h"
#include "scene/scene.h"
#include "testkit/example_scenes.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

using namespace ib;
using namespace ib::gltf;

namespace fs = std::filesystem;

namespace {

// n vertices on a line, moved by `motion(t)` at time t.
std::vector<Eigen::MatrixX2d> movingFrames(int frames, const std::function<Eigen::Vector2d(double t)>& motion,
                                           std::vector<double>& times) {
  std::vector<Eigen::MatrixX2d> out;
  times.clear();
  for (int f = 0; f < frames; ++f) {
    const double t = f / 24.0;
    Eigen::MatrixX2d x(5, 2);
    for (int v = 0; v < 5; ++v) x.row(v) = Eigen::RowVector2d(10.0 * v, 3.0 * v) + motion(t).transpose();
    out.push_back(x);
    times.push_back(t);
  }
  return out;
}

bool acceptImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;  // the images' bytes are not decoded here (the browser test looks at them)
}

struct Exported {
  tinygltf::Model model;
  BakedAnimation baked;
  GltfExportReport report;
};

// A bundled scene (initial map, no Comesh, for speed), frames 0..lastFrame, exported with `options`
// to `out`; result.model is left empty.
Exported writeScene(const std::string& file, const GltfExportOptions& options, const std::string& out, int lastFrame) {
  const Scene scene = loadScene(file);
  SceneMultimeshOptions meshOptions;
  meshOptions.useCache = false;
  meshOptions.comesh = false;
  const std::shared_ptr<const Multimesh> mesh = sceneMultimesh(scene, meshOptions).multimesh;
  std::vector<RgbaImage> drawings = readKeyDrawings(scene);
  ExportedScene exported;
  exported.name = fs::path(file).parent_path().filename().string();
  for (const KeySpec& key : scene.keys) exported.keyNames.push_back(key.name);
  for (const RgbaImage& d : drawings) exported.canvas = {std::max(exported.canvas[0], d.width), std::max(exported.canvas[1], d.height)};
  const render::RenderMesh renderMesh = render::renderMeshOf(*mesh, std::move(drawings));
  FrameStream stream = sceneFrameStream(scene, *mesh);
  Exported result;
  result.baked = bakeAnimation(stream, renderMesh.cutSides, {0, std::min(lastFrame, stream.frameCount() - 1)});
  result.report = writeGltf(result.baked, renderMesh, exported, options, out);
  return result;
}

// The same, read back by tinygltf's loader.
Exported exportScene(const std::string& file, const GltfExportOptions& options, const std::string& out, int lastFrame) {
  Exported result = writeScene(file, options, out, lastFrame);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&acceptImage, nullptr);
  std::string error, warning;
  const bool loaded = loader.LoadBinaryFromFile(&result.model, &error, &warning, out);
  INFO(error << warning);
  REQUIRE(loaded);
  return result;
}

template <typename T>
const T* accessorData(const tinygltf::Model& model, int accessor) {
  const tinygltf::Accessor& a = model.accessors[accessor];
  const tinygltf::BufferView& view = model.bufferViews[a.bufferView];
  return reinterpret_cast<const T*>(model.buffers[view.buffer].data.data() + view.byteOffset + a.byteOffset);
}

}  // namespace

TEST_CASE("export: reduceFrames at bound 0 keeps every frame, and a linear motion keeps only its ends") {
  std::vector<double> times;
  const std::vector<Eigen::MatrixX2d> linear =
      movingFrames(30, [](double t) { return Eigen::Vector2d(40 * t, -12 * t); }, times);
  const auto exact = [&](int f) { return linear[f]; };
  const FrameReduction all = reduceFrames(linear, exact, times, 0);
  CHECK(all.kept.size() == 30);
  const FrameReduction ends = reduceFrames(linear, exact, times, 1e-9);
  CHECK(ends.kept == std::vector<int>{0, 29});
  CHECK(ends.maxError < 1e-9);
}

TEST_CASE("export: reduceFrames' linear blend of kept frames is within the bound at every frame time") {
  std::vector<double> times;
  const std::vector<Eigen::MatrixX2d> wave =
      movingFrames(97, [](double t) { return Eigen::Vector2d(30 * std::sin(4 * t), 10 * t * t); }, times);
  for (double bound : {0.01, 0.1, 0.5, 2.0}) {
    const FrameReduction r = reduceFrames(wave, [&](int f) { return wave[f]; }, times, bound);
    INFO("bound " << bound << " px: " << r.kept.size() << " of 97 frames kept");
    REQUIRE(r.kept.front() == 0);
    REQUIRE(r.kept.back() == 96);
    if (bound >= 0.5) CHECK(r.kept.size() < 97);  // the wave's frames curve by about 0.4 px per frame
    double worst = 0;
    for (size_t k = 0; k + 1 < r.kept.size(); ++k) {
      const int i = r.kept[k], j = r.kept[k + 1];
      for (int f = i; f <= j; ++f) {
        const double u = (times[f] - times[i]) / (times[j] - times[i]);
        worst = std::max(worst, ((1 - u) * wave[i] + u * wave[j] - wave[f]).rowwise().norm().maxCoeff());
      }
    }
    CHECK(worst <= bound);
    CHECK(r.maxError == Approx(worst).margin(1e-12));
  }
}

TEST_CASE("export: layers drawn bottom to top at layerAlphas give every opaque key its weight") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd w(6);
    for (int k = 0; k < 6; ++k) w[k] = uniform(random) < 0.4 ? 0.0 : uniform(random);
    if (w.sum() == 0) w[2] = 1;
    w /= w.sum();
    const std::vector<double> a = layerAlphas(w);
    // Over-compositing opaque layers: layer k's share is a_k times what the layers above let through.
    for (int k = 0; k < 6; ++k) {
      double share = a[k];
      for (int j = k + 1; j < 6; ++j) share *= 1 - a[j];
      CHECK(share == Approx(w[k]).margin(1e-12));
    }
  }
}

TEST_CASE("export: PositionCodec puts drawing pixels at glTF units, y up, origin at the canvas centre") {
  Eigen::MatrixX2d base(3, 2);
  base << 0, 0, 128, 64, 64, 32;
  const PositionCodec codec({128, 64}, 100, false, base, {base});
  const std::vector<float> stored = codec.base();
  CHECK(stored[0] == Approx(-0.64f));  // (0 - 64) / 100
  CHECK(stored[1] == Approx(0.32f));   // (32 - 0) / 100: y up
  CHECK(stored[3] == Approx(0.64f));
  CHECK(stored[4] == Approx(-0.32f));
  CHECK(stored[6] == 0.0f);
  CHECK(stored[7] == 0.0f);
  CHECK(stored[2] == 0.0f);
  CHECK((codec.decoded(base) - base).cwiseAbs().maxCoeff() < 1e-4);
}

TEST_CASE("export: quantized morph targets decode within half a 16-bit step of the largest delta") {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-50, 50);
  Eigen::MatrixX2d base(40, 2);
  for (int v = 0; v < 40; ++v) base.row(v) << 100 + uniform(random), 80 + uniform(random);
  std::vector<Eigen::MatrixX2d> frames{base};
  for (int f = 0; f < 5; ++f) {
    Eigen::MatrixX2d x = base;
    for (int v = 0; v < 40; ++v) x.row(v) += Eigen::RowVector2d(uniform(random), uniform(random)) * (f + 1) / 5.0;
    frames.push_back(x);
  }
  const PositionCodec codec({256, 256}, 100, true, base, frames);
  double largest = 0;
  for (const Eigen::MatrixX2d& x : frames) largest = std::max(largest, (x - base).cwiseAbs().maxCoeff());
  const double step = largest / 32767;  // drawing pixels
  for (const Eigen::MatrixX2d& x : frames) CHECK((codec.decoded(x) - x).cwiseAbs().maxCoeff() <= 0.5 * step + 1e-6);
}

TEST_CASE("export: every bundled scene read back by tinygltf has one layer per drawn key, min/max and at most two active targets") {
  const fs::path dir = fs::temp_directory_path() / ("inbetween-export-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const std::string& file : test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    INFO(file);
    const Exported e = exportScene(file, {}, (dir / "scene.glb").string(), 30);
    const tinygltf::Model& model = e.model;
    // The shape's mesh, and where a cut opens in a drawing inked round its outline (arch-split's
    // bricks) the ink's in a node of its own (test_export_ink.cpp).
    REQUIRE((model.meshes.size() == 1 || (model.meshes.size() == 2 && model.meshes[1].name == model.meshes[0].name + " ink")));
    REQUIRE(model.nodes.size() == model.meshes.size());
    const tinygltf::Mesh& mesh = model.meshes[0];
    int drawnKeys = 0;
    for (Eigen::Index k = 0; k < e.baked.weights.front().size(); ++k) {
      bool drawn = false;
      for (const Eigen::VectorXd& w : e.baked.weights) drawn = drawn || w[k] > 0;
      drawnKeys += drawn;
    }
    CHECK(static_cast<int>(mesh.primitives.size()) == drawnKeys);
    CHECK(static_cast<int>(mesh.primitives[0].targets.size()) == static_cast<int>(e.baked.frames.size()) - 1);
    for (const tinygltf::Primitive& p : mesh.primitives) {
      CHECK(p.attributes.at("POSITION") == mesh.primitives[0].attributes.at("POSITION"));
      CHECK(model.materials[p.material].alphaMode == "BLEND");
      for (const auto& target : p.targets) {
        const tinygltf::Accessor& a = model.accessors[target.at("POSITION")];
        CHECK(a.minValues.size() == 3);
        CHECK(a.maxValues.size() == 3);
      }
    }
    REQUIRE(model.animations.size() == 1);
    const tinygltf::AnimationChannel& weights = model.animations[0].channels[0];
    REQUIRE(weights.target_path == "weights");
    const tinygltf::AnimationSampler& sampler = model.animations[0].samplers[weights.sampler];
    const tinygltf::Accessor& input = model.accessors[sampler.input];
    CHECK(input.minValues.size() == 1);
    CHECK(input.maxValues.size() == 1);
    const size_t targets = mesh.primitives[0].targets.size();
    const float* w = accessorData<float>(model, sampler.output);
    for (size_t key = 0; key < input.count; ++key) {
      int active = 0;
      for (size_t t = 0; t < targets; ++t) active += w[key * targets + t] != 0.0f;
      CHECK(active <= 1);  // one per keyframe, so at most two between neighbouring keyframes
    }
    CHECK(e.report.maxError < 1e-4 * e.baked.shapeSize);
  }
  fs::remove_all(dir);
}

TEST_CASE("export: a path that cannot be written is an InputError and leaves no file") {
  const std::string file = std::string(INBETWEEN_ASSETS) + "/square-arch-notch/scene.json";
  const fs::path dir = fs::temp_directory_path() / ("inbetween-export-unwritable-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path blocked = dir / "not-a-folder";
  { std::ofstream(blocked.string()) << "a file where a folder should be"; }
  CHECK_THROWS_AS(exportScene(file, {}, (blocked / "out.glb").string(), 4), InputError);
  CHECK_THROWS_AS(exportScene(file, {}, (blocked / "out.gltf").string(), 4), InputError);
  CHECK_THROWS_AS(exportScene(file, {}, (dir / "out.png").string(), 4), InputError);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  fs::remove_all(dir);
}

TEST_CASE("export: a --meshopt .glb names every compressed bufferView's codec and its fallback buffer") {
  const std::string file = std::string(INBETWEEN_ASSETS) + "/square-arch-notch/scene.json";
  const fs::path dir = fs::temp_directory_path() / ("inbetween-export-meshopt-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string out = (dir / "notch.glb").string();
  GltfExportOptions options;
  options.meshopt = true;
  writeScene(file, options, out, 8);
  // The JSON chunk: 12-byte header, then its length and type.
  std::ifstream in(out, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() > 20);
  uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, bytes.data() + 12, 4);
  const nlohmann::json json = nlohmann::json::parse(bytes.substr(20, jsonLength));
  REQUIRE(json["buffers"].size() == 2);
  CHECK(json["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"] == true);
  CHECK(!json["buffers"][1].contains("uri"));
  int compressed = 0;
  for (const nlohmann::json& view : json["bufferViews"]) {
    if (!view.contains("extensions")) {
      CHECK(view["buffer"] == 0);  // the images
      continue;
    }
    const nlohmann::json& ext = view["extensions"]["EXT_meshopt_compression"];
    CHECK(view["buffer"] == 1);
    CHECK(ext["buffer"] == 0);
    CHECK(ext["byteStride"].get<int>() * ext["count"].get<int>() == view["byteLength"].get<int>());
    CHECK((ext["mode"] == "ATTRIBUTES" || ext["mode"] == "TRIANGLES"));
    ++compressed;
  }
  CHECK(compressed >= 4);  // indices, base, a target, UVs, animation
  const std::vector<std::string> required = json["extensionsRequired"];
  CHECK(std::count(required.begin(), required.end(), "EXT_meshopt_compression") == 1);
  CHECK(std::count(required.begin(), required.end(), "KHR_mesh_quantization") == 1);
  fs::remove_all(dir);
}
