// The scene-to-multimesh pipeline front ends call (pipeline/scene_multimesh.h): where the
// multimesh comes from (a given file, the cache beside the scene, a build), what a build reports,
// and its progress. Its headers come first in this file, so the guards below tell what they pull
// in: a front end that includes them sees none of OpenMesh, OpenMP, the factorization or nlohmann.
#include "pipeline/key_drawings.h"
#include "pipeline/scene_multimesh.h"

#if defined(OPENMESH_CONFIG_H) || defined(OPENMESH_TRIMESH_ARRAY_KERNEL_HH)
#error "the pipeline's headers include OpenMesh"
#endif
#if defined(_OMP_H)
#error "the pipeline's headers include omp.h"
#endif
#if defined(EIGEN_SPARSECORE_MODULE_H) || defined(EIGEN_SPARSE_MODULE_H)
#error "the pipeline's headers include Eigen's sparse modules (the factorization)"
#endif
#if defined(INCLUDE_NLOHMANN_JSON_HPP_)
#error "the pipeline's headers include nlohmann/json"
#endif

#include "comesh/comesh.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "meshing/key_shape.h"
#include "multimesh/multimesh.h"
#include "multimesh/multimesh_io.h"
#include "scene/scene.h"
#include "testkit/drawings.h"
#include "testkit/example_scenes.h"
#include "testkit/shape_generators.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <utility>
#include <vector>

using namespace ib;
namespace fs = std::filesystem;

namespace {

// The example scene `name` written into a fresh scratch folder of its own, loaded, with twice its
// edge length: these cases are about where a multimesh comes from, and a coarser one builds faster.
Scene writeExample(const std::string& name, const std::string& folder) {
  std::vector<test::ExampleScene> all = test::goodScenes();
  for (const auto& scene : test::comeshScenes()) all.push_back(scene);
  for (const auto& example : all)
    if (example.name == name) {
      const std::string dir = test::scratchDirectory(folder);
      test::writeScene(example, dir);
      Scene scene = loadScene((fs::path(dir) / name / "scene.json").string());
      scene.edgeLength *= 2;
      return scene;
    }
  throw std::logic_error("no example scene " + name);
}

// Sets the modification time of the scene file and every drawing to `inputs`, and of `cache` to
// `cached`: freshness is decided by these times alone, not by how fast the test wrote the files.
void setTimes(const Scene& scene, const std::string& cache, fs::file_time_type inputs, fs::file_time_type cached) {
  fs::last_write_time(scene.file, inputs);
  for (const KeySpec& key : scene.keys) fs::last_write_time(key.drawing, inputs);
  fs::last_write_time(cache, cached);
}

SceneMultimeshOptions withoutComesh() {
  SceneMultimeshOptions options;
  options.comesh = false;  // the initial map alone: the cases below are about where it comes from
  return options;
}

// Every (stage, fraction) a call reports.
std::vector<std::pair<std::string, double>> progressOf(const Scene& scene, const SceneMultimeshOptions& options) {
  std::vector<std::pair<std::string, double>> out;
  sceneMultimesh(scene, options, [&](const std::string& stage, double fraction) { out.emplace_back(stage, fraction); });
  return out;
}

void checkProgress(const std::vector<std::pair<std::string, double>>& reports) {
  REQUIRE(!reports.empty());
  for (size_t i = 0; i < reports.size(); ++i) {
    INFO("report " << i << ": " << reports[i].first << " at " << reports[i].second);
    CHECK(reports[i].second >= 0);
    CHECK(reports[i].second <= 1);
    if (i > 0) CHECK(reports[i].second >= reports[i - 1].second);
  }
  CHECK(reports.back().second == 1.0);  // the last report is exactly 1, not merely close
}

}  // namespace

TEST_CASE("pipeline: a cache newer than the scene and its drawings is used") {
  const Scene scene = writeExample("square-arch-notch", "pipeline-fresh");
  const std::string cache = cachedMeshPath(scene.file);
  saveMultimesh(*sceneMultimesh(scene, withoutComesh()).multimesh, cache);
  const auto now = fs::file_time_type::clock::now();
  setTimes(scene, cache, now - std::chrono::hours(1), now);
  const SceneMultimesh used = sceneMultimesh(scene, withoutComesh());
  CHECK(used.source == MeshSource::kCache);
  CHECK(used.file == cache);
  CHECK(used.initial == nullptr);  // nothing was built: no initial map, no report
  CHECK(used.shapes.empty());
  CHECK(used.comesh == nullptr);
  CHECK(used.multimesh->keyCount() == 2);
}

TEST_CASE("pipeline: a cache older than the scene file or a drawing is rebuilt") {
  const Scene scene = writeExample("square-arch-notch", "pipeline-stale");
  const std::string cache = cachedMeshPath(scene.file);
  saveMultimesh(*sceneMultimesh(scene, withoutComesh()).multimesh, cache);
  const auto now = fs::file_time_type::clock::now();
  SECTION("the scene file is newer") {
    setTimes(scene, cache, now - std::chrono::hours(1), now);
    fs::last_write_time(scene.file, now + std::chrono::seconds(1));
  }
  SECTION("a drawing is newer") {
    setTimes(scene, cache, now - std::chrono::hours(1), now);
    fs::last_write_time(scene.keys[1].drawing, now + std::chrono::seconds(1));
  }
  const SceneMultimesh rebuilt = sceneMultimesh(scene, withoutComesh());
  CHECK(rebuilt.source == MeshSource::kBuilt);
  CHECK(rebuilt.file.empty());
  CHECK(rebuilt.shapes.size() == 2);
}

TEST_CASE("pipeline: a corrupt cache, or one with another key count, is rebuilt, not an error") {
  const Scene scene = writeExample("square-arch-notch", "pipeline-corrupt");
  const std::string cache = cachedMeshPath(scene.file);
  SECTION("corrupt") { writeFileAtomically(cache, "IBMMESH but not a multimesh"); }
  SECTION("four keys for a scene of two") { saveMultimesh(benchmarkStrip(100, 4), cache); }
  const auto now = fs::file_time_type::clock::now();
  setTimes(scene, cache, now - std::chrono::hours(1), now);
  const SceneMultimesh rebuilt = sceneMultimesh(scene, withoutComesh());
  CHECK(rebuilt.source == MeshSource::kBuilt);
  CHECK(rebuilt.multimesh->keyCount() == 2);
}

TEST_CASE("pipeline: without the cache option a current cache is not read") {
  const Scene scene = writeExample("square-arch-notch", "pipeline-nocache");
  const std::string cache = cachedMeshPath(scene.file);
  writeFileAtomically(cache, "not read");
  const auto now = fs::file_time_type::clock::now();
  setTimes(scene, cache, now - std::chrono::hours(1), now);
  SceneMultimeshOptions options = withoutComesh();
  options.useCache = false;
  CHECK(sceneMultimesh(scene, options).source == MeshSource::kBuilt);
}

TEST_CASE("pipeline: a mesh file is used whatever its age, and one with the wrong key count is an InputError naming both files") {
  const Scene scene = writeExample("square-arch-notch", "pipeline-file");
  SceneMultimeshOptions options = withoutComesh();
  options.meshFile = (fs::path(scene.file).parent_path() / "given.ibmesh").string();
  SECTION("the scene's key count") {
    saveMultimesh(*sceneMultimesh(scene, withoutComesh()).multimesh, options.meshFile);
    fs::last_write_time(options.meshFile, fs::file_time_type::clock::now() - std::chrono::hours(1));
    const SceneMultimesh given = sceneMultimesh(scene, options);
    CHECK(given.source == MeshSource::kFile);
    CHECK(given.file == options.meshFile);
  }
  SECTION("four keys for a scene of two") {
    saveMultimesh(benchmarkStrip(100, 4), options.meshFile);
    try {
      sceneMultimesh(scene, options);
      FAIL("no error");
    } catch (const InputError& e) {
      const std::string message = e.what();
      CHECK(message.find(options.meshFile) != std::string::npos);
      CHECK(message.find(scene.file) != std::string::npos);
      CHECK(message.find("4 keys") != std::string::npos);
    }
  }
  SECTION("missing") {
    options.meshFile += ".missing";
    CHECK_THROWS_AS(sceneMultimesh(scene, options), InputError);
  }
}

TEST_CASE("pipeline: progress fractions never decrease and end at 1, built with and without Comesh, and loaded") {
  const Scene scene = writeExample("pentagon-star", "pipeline-progress");
  ComeshOptions comesh;
  comesh.outerIterations = 4;  // a few are enough to see Comesh's share of the bar move
  SceneMultimeshOptions options;
  options.useCache = false;
  options.comeshOptions = &comesh;
  SECTION("built with Comesh") { checkProgress(progressOf(scene, options)); }
  SECTION("built without Comesh") {
    options.comesh = false;
    checkProgress(progressOf(scene, options));
  }
  SECTION("loaded") {
    options.meshFile = (fs::path(scene.file).parent_path() / "given.ibmesh").string();
    saveMultimesh(benchmarkStrip(100, 2), options.meshFile);
    checkProgress(progressOf(scene, options));
  }
}

TEST_CASE("pipeline: with Comesh the result holds the initial map, the optimized multimesh and Comesh's statistics") {
  const Scene scene = writeExample("pentagon-star", "pipeline-comesh");
  ComeshOptions comesh;
  comesh.outerIterations = 3;
  int calls = 0;
  comesh.progress = [&](int, double) { ++calls; };  // the caller's callback is still called
  SceneMultimeshOptions options;
  options.useCache = false;
  options.comeshOptions = &comesh;
  const SceneMultimesh built = sceneMultimesh(scene, options);
  CHECK(built.source == MeshSource::kBuilt);
  REQUIRE(built.initial != nullptr);
  REQUIRE(built.comesh != nullptr);
  CHECK(built.initial != built.multimesh);
  CHECK(built.comesh->outerIterations >= 1);
  CHECK(built.comesh->outerIterations <= 3);  // the given options were used, not the defaults (500)
  CHECK(calls == built.comesh->outerIterations);
  CHECK(built.comesh->verticesIn == built.initial->vertexCount());
  CHECK(built.comesh->verticesOut == built.multimesh->vertexCount());
  CHECK(built.shapes.size() == scene.keys.size());
  CHECK(built.drawingSizes.size() == scene.keys.size());
  CHECK(built.edgeLength > 0);
  CHECK_NOTHROW(built.multimesh->validate());
}

TEST_CASE("pipeline: without Comesh the initial map is the multimesh and there are no Comesh statistics") {
  const Scene scene = writeExample("pentagon-star", "pipeline-initial");
  SceneMultimeshOptions options = withoutComesh();
  options.useCache = false;
  const SceneMultimesh built = sceneMultimesh(scene, options);
  REQUIRE(built.initial != nullptr);
  CHECK(built.initial == built.multimesh);
  CHECK(built.comesh == nullptr);
  CHECK(built.shapes.size() == scene.keys.size());
}

TEST_CASE("pipeline: feature vertices are boundary vertices at the scene's features, sorted and distinct") {
  const Scene scene = writeExample("square-arch-notch", "pipeline-features");
  const SceneMultimesh built = sceneMultimesh(scene, withoutComesh());
  const Multimesh& mesh = *built.multimesh;
  const std::vector<int> features = featureVertices(scene, mesh);
  REQUIRE(!features.empty());
  for (size_t i = 1; i < features.size(); ++i) CHECK(features[i - 1] < features[i]);
  for (int v : features) CHECK(mesh.onBoundary()[v]);
  // Features are snapped onto the traced outline, at most scene.edgeLength (8 px) off their
  // placed point; the mesh has a vertex there.
  for (size_t k = 0; k < scene.keys.size(); ++k)
    for (const auto& [name, point] : scene.keys[k].features) {
      double nearest = 1e9;
      for (int v : features) nearest = std::min(nearest, (mesh.keyPositions(static_cast<int>(k)).row(v).transpose() - point).norm());
      INFO("key " << scene.keys[k].name << ", feature " << name);
      CHECK(nearest <= scene.edgeLength);
    }
}

TEST_CASE("pipeline: a drawing that cannot be read is an InputError naming the scene file, the key and the drawing") {
  const std::string folder = test::scratchDirectory("pipeline-drawings");
  for (const auto& example : test::goodScenes())
    if (example.name == "square-arch-notch") test::writeScene(example, folder);  // the bad scenes' drawings
  test::writeBadScenes(folder);
  const Scene scene = loadScene((fs::path(folder) / "bad" / "missing-drawing.json").string());
  try {
    readKeyDrawings(scene);
    FAIL("no error");
  } catch (const InputError& e) {
    const std::string message = e.what();
    CHECK(message.find("missing-drawing.json: key \"square\": drawing ") == 0);
    CHECK(message.find("no-such-drawing.png") != std::string::npos);
  }
}

TEST_CASE("pipeline: readKeyDrawings reads every key's drawing at its size") {
  const Scene scene = writeExample("square-arch-notch", "pipeline-read");
  const std::vector<RgbaImage> drawings = readKeyDrawings(scene);
  const SceneMultimesh built = sceneMultimesh(scene, withoutComesh());
  REQUIRE(drawings.size() == scene.keys.size());
  for (size_t k = 0; k < drawings.size(); ++k) {
    CHECK(drawings[k].width == built.drawingSizes[k][0]);
    CHECK(drawings[k].height == built.drawingSizes[k][1]);
  }
}

TEST_CASE("pipeline: keys on canvases of different sizes and a one-key scene come with notes, whatever the source") {
  const std::string folder = test::scratchDirectory("pipeline-notes");
  ib::writePng(folder + "/a.png", test::drawShape(128, 128, test::box(28, 28, 100, 100)));
  ib::writePng(folder + "/b.png", test::drawShape(140, 128, test::box(28, 28, 100, 100)));
  const auto write = [&](const std::string& name, const std::string& keys) {
    writeFileAtomically(folder + "/" + name, R"({"version": 1, "edge_length": 12, "keys": [)" + keys + "]}");
    return loadScene(folder + "/" + name);
  };
  const Scene same = write("same.json", R"({"name": "a", "drawing": "a.png"}, {"name": "a2", "drawing": "a.png"})");
  CHECK(sceneNotes(same).empty());
  const Scene sizes = write("sizes.json", R"({"name": "a", "drawing": "a.png"}, {"name": "b", "drawing": "b.png"})");
  const std::string canvas =
      "sizes.json: keys have different canvas sizes (128x128 for \"a\", 140x128 for \"b\"): positions are drawing pixels "
      "from each drawing's top-left, so the drawings line up at their top-left corners; the renderer's canvas is the "
      "largest, 140x128 (draw every key on the same canvas to place them otherwise)";
  CHECK(sceneNotes(sizes) == std::vector<std::string>{canvas});
  SceneMultimeshOptions options;
  options.comesh = false;
  const SceneMultimesh built = sceneMultimesh(sizes, options);
  CHECK(built.notes == std::vector<std::string>{canvas});
  saveMultimesh(*built.multimesh, folder + "/sizes.ibmesh");
  options.meshFile = folder + "/sizes.ibmesh";
  CHECK(sceneMultimesh(sizes, options).notes == std::vector<std::string>{canvas});
  const Scene one = write("one.json", R"({"name": "a", "drawing": "a.png"})");
  REQUIRE(sceneNotes(one).size() == 1);
  CHECK(sceneNotes(one)[0].rfind("one.json: one key (\"a\"): the animation is a still", 0) == 0);
  // A drawing that cannot be read gives no canvas note: reading it says what is wrong.
  const Scene missing = write("missing.json", R"({"name": "a", "drawing": "a.png"}, {"name": "b", "drawing": "none.png"})");
  CHECK(sceneNotes(missing).empty());
}
