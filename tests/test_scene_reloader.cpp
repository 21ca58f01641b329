// Reloading the player's scene when its files change (engine/playback/scene_reloader.h): the
// first load gives a mesh, a changed drawing is rebuilt in the background and swapped in on
// takeReloaded(), and a broken edit reports an error while the last good scene stays. The
// playback headers come first, so the guards below tell what they pull in.
#include "playback/live_parameters.h"
#include "playback/scene_parameters.h"
#include "playback/scene_reloader.h"
#include "playback/transport.h"

// The player's headers are thin, as the solver's front-end headers (test_public_headers.cpp; omp.h
// is not checked here: this program is built with OpenMP, under which Eigen's core includes it).
#if defined(OPENMESH_CONFIG_H) || defined(OPENMESH_TRIMESH_ARRAY_KERNEL_HH)
#error "a playback header includes OpenMesh"
#endif
#if defined(EIGEN_SPARSECORE_MODULE_H) || defined(EIGEN_SPARSE_MODULE_H)
#error "a playback header includes Eigen's sparse modules"
#endif
#if defined(INCLUDE_NLOHMANN_JSON_HPP_)
#error "a playback header includes nlohmann/json"
#endif

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/png_image.h"
#include "multimesh/multimesh.h"
#include "testkit/drawings.h"
#include "testkit/example_scenes.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>

using namespace ib;
using ib::play::SceneReloader;
namespace fs = std::filesystem;

namespace {

// square-arch-stretch in a fresh scratch folder at twice its edge length (a coarser mesh builds
// faster; these cases are about when it is rebuilt). Returns the scene file.
std::string writtenScene(const std::string& folder) {
  for (const auto& example : test::goodScenes())
    if (example.name == "square-arch-stretch") {
      const std::string dir = test::scratchDirectory(folder);
      test::writeScene(example, dir);
      const std::string file = (fs::path(dir) / example.name / "scene.json").string();
      nlohmann::ordered_json j = nlohmann::ordered_json::parse(readFile(file));
      j["edge_length"] = j["edge_length"].get<double>() * 2;
      writeFileAtomically(file, j.dump(2));
      return file;
    }
  throw std::logic_error("no example scene square-arch-stretch");
}

// Waits for the background rebuild to finish; false after `seconds` without.
bool waitIdle(const SceneReloader& reloader, double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (reloader.busy()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// A file's modification time moved `seconds` past its current one: a change poll() must see
// however coarse the file system's clock.
void later(const std::string& file, int seconds) {
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(seconds));
}

// Build time allowance for the coarse scene, with room for a loaded machine.
constexpr double kBuildSeconds = 300;

// Saves `params` (at 12 fps) into the reloader's scene file, moves its time `seconds` on, polls
// and requires the reload.
void saveAndReload(SceneReloader& reloader, play::LiveParameters& params, int seconds) {
  const std::string file = reloader.path();
  play::saveParameters(file, params, 12);
  later(file, seconds);
  reloader.poll();
  REQUIRE(waitIdle(reloader, kBuildSeconds));
  CHECK_FALSE(reloader.takeError());
  REQUIRE(reloader.takeReloaded());
}

}  // namespace

TEST_CASE("scene reloader: the first load gives the scene, its mesh, drawings and features, with no rebuild pending") {
  const std::string file = writtenScene("reloader-first");
  SceneReloader reloader(file);
  const play::LoadedScene& loaded = reloader.current();
  REQUIRE(loaded.mesh);
  CHECK(loaded.mesh->keyCount() == 2);
  CHECK(loaded.initial);  // built now: the initial map is known
  REQUIRE(loaded.drawings.size() == 2);
  CHECK(loaded.drawings[0].width > 0);
  CHECK_FALSE(loaded.features.empty());
  CHECK(loaded.scene.file == file);
  CHECK_FALSE(reloader.busy());
  CHECK(reloader.progress() == 1);
  reloader.poll();  // nothing changed
  CHECK_FALSE(reloader.busy());
  CHECK_FALSE(reloader.takeReloaded());
  CHECK_FALSE(reloader.takeError());
}

TEST_CASE("scene reloader: a bad scene is an input error when first loaded") {
  const std::string dir = test::scratchDirectory("reloader-bad");
  const std::string file = (fs::path(dir) / "scene.json").string();
  writeFileAtomically(file, "{\"version\": 1, \"keys\": [");
  CHECK_THROWS_AS(SceneReloader(file), InputError);
}

TEST_CASE("scene reloader: a changed drawing is rebuilt in the background and swapped in once by takeReloaded") {
  const std::string file = writtenScene("reloader-drawing");
  SceneReloader reloader(file);
  const std::shared_ptr<const Multimesh> before = reloader.current().mesh;
  const std::string drawing = reloader.current().scene.keys[1].drawing;

  RgbaImage changed = readPng(drawing);
  for (size_t i = 0; i + 3 < changed.pixels.size(); i += 4) changed.pixels[i] = 200;  // redder ink, same shape
  writePng(drawing, changed);
  later(drawing, 10);

  reloader.poll();
  CHECK(reloader.busy());
  REQUIRE(waitIdle(reloader, kBuildSeconds));
  CHECK_FALSE(reloader.takeError());
  REQUIRE(reloader.takeReloaded());
  CHECK_FALSE(reloader.takeReloaded());
  CHECK(reloader.current().mesh != before);
  CHECK(reloader.current().drawings[1].pixels == changed.pixels);
  reloader.poll();  // the change was taken in: no other rebuild
  CHECK_FALSE(reloader.busy());
}

TEST_CASE("scene reloader: a broken edit reports an error naming the file, and the last good scene stays current") {
  const std::string file = writtenScene("reloader-broken");
  SceneReloader reloader(file);
  const std::shared_ptr<const Multimesh> before = reloader.current().mesh;
  const auto keys = reloader.current().scene.keys.size();

  writeFileAtomically(file, "{\"version\": 1, \"keys\": [");
  later(file, 10);
  reloader.poll();
  REQUIRE(waitIdle(reloader, kBuildSeconds));
  const std::optional<std::string> error = reloader.takeError();
  REQUIRE(error);
  CHECK_THAT(*error, Catch::Contains("scene.json"));
  CHECK_FALSE(reloader.takeError());  // once
  CHECK_FALSE(reloader.takeReloaded());
  CHECK(reloader.current().mesh == before);
  CHECK(reloader.current().scene.keys.size() == keys);
  reloader.poll();  // the broken file is not retried until it changes again
  CHECK_FALSE(reloader.busy());
}

TEST_CASE("scene reloader: reloadNow rebuilds unconditionally, and a second request during it runs after it") {
  const std::string file = writtenScene("reloader-now");
  SceneReloader reloader(file);
  reloader.reloadNow();
  reloader.reloadNow();  // queued behind the first
  CHECK(reloader.busy());
  REQUIRE(waitIdle(reloader, 2 * kBuildSeconds));
  CHECK_FALSE(reloader.takeError());
  CHECK(reloader.takeReloaded());
  CHECK_FALSE(reloader.takeReloaded());  // the later build replaced the earlier one untaken
}

TEST_CASE("scene reloader: saved parameters reload the scene keeping its multimesh, a new kappa rebuilds it") {
  const std::string file = writtenScene("reloader-saved");
  SceneReloader reloader(file);
  const std::shared_ptr<const Multimesh> before = reloader.current().mesh;

  play::LiveParameters tuned(reloader.current().scene);
  tuned.set("tau", 1e-4);
  tuned.set("epsilon", 0.2);
  saveAndReload(reloader, tuned, 10);
  CHECK(reloader.current().mesh == before);
  CHECK(reloader.current().scene.interpolation.cohesive.tau == 1e-4);
  CHECK(reloader.current().scene.dynamics.epsilon == 0.2);
  CHECK(reloader.current().scene.timeline.fps() == 12);

  play::LiveParameters stiffer(reloader.current().scene);
  stiffer.set("kappa_scale", 2);
  saveAndReload(reloader, stiffer, 20);
  CHECK(reloader.current().mesh != before);
  CHECK(reloader.current().scene.kappa == 2);
}

TEST_CASE("scene reloader: open loads another scene in the background, a failed open keeps the current one") {
  const std::string file = writtenScene("reloader-open");
  const std::string other = writtenScene("reloader-open-other");
  SceneReloader reloader(file);

  reloader.open((fs::path(other).parent_path() / "missing.json").string());
  REQUIRE(waitIdle(reloader, kBuildSeconds));
  const std::optional<std::string> error = reloader.takeError();
  REQUIRE(error);
  CHECK_THAT(*error, Catch::Contains("missing.json"));
  CHECK_FALSE(reloader.takeReloaded());
  CHECK(reloader.path() == file);

  reloader.open(other);
  REQUIRE(waitIdle(reloader, kBuildSeconds));
  CHECK_FALSE(reloader.takeError());
  REQUIRE(reloader.takeReloaded());
  CHECK(reloader.path() == other);
  CHECK(reloader.current().scene.file == other);
  later(other, 10);  // the opened scene is the one watched now
  reloader.poll();
  CHECK(reloader.busy());
  REQUIRE(waitIdle(reloader, kBuildSeconds));
  CHECK(reloader.takeReloaded());
}

TEST_CASE("scene reloader: an editor's text builds without the file, its scene carries the request's number, and an "
          "optimized build of an older text is cancelled by a newer quick one, without an error") {
  const std::string file = writtenScene("reloader-text");
  SceneReloader reloader(file);
  const int keyVertices = reloader.current().mesh->vertexCount();
  // The same scene at a finer edge length, as text only: the file on disk is unchanged.
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(readFile(file));
  j["edge_length"] = j["edge_length"].get<double>() / 2;
  const int quick = reloader.rebuildFromText(j.dump(2), false);
  REQUIRE(waitIdle(reloader, kBuildSeconds));
  CHECK_FALSE(reloader.takeError());
  REQUIRE(reloader.takeReloaded());
  CHECK(reloader.current().build == quick);
  CHECK(reloader.current().mesh->vertexCount() > keyVertices);
  CHECK(reloader.current().scene.edgeLength == Approx(j["edge_length"].get<double>()));
  CHECK(nlohmann::ordered_json::parse(readFile(file))["edge_length"].get<double>() == Approx(2 * j["edge_length"].get<double>()));

  // An optimized build, then at once a quick build of another text: the first is cancelled (or,
  // on a fast machine, finishes first) and the last text's scene is what stays.
  reloader.rebuildFromText(j.dump(2), true);
  j["edge_length"] = j["edge_length"].get<double>() * 1.5;
  const int last = reloader.rebuildFromText(j.dump(2), false);
  CHECK(last > quick);
  REQUIRE(waitIdle(reloader, 2 * kBuildSeconds));
  CHECK_FALSE(reloader.takeError());
  REQUIRE(reloader.takeReloaded());
  CHECK(reloader.current().build == last);
  CHECK(reloader.current().scene.edgeLength == Approx(j["edge_length"].get<double>()));
}
