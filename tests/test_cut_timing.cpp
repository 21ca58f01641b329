// A cut's own timing in the scene (docs/scene-format.md, "Cut timing"): it moves when the cut
// lets go, the scrubber's events fall where the weights cross it, and the keys that draw a cut
// agree on it.
#include "animation/frame_stream.h"
#include "meshing/multimesh_builder.h"
#include "pipeline/cut_timing.h"
#include "pipeline/scene_frames.h"
#include "scene/scene.h"
#include "testkit/errors.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace ib;

namespace {

const std::string kChomp = std::string(INBETWEEN_SOURCE_DIR) + "/tests/topology/chomp/scene.json";

// The open key's weight at the first frame where some pair no longer holds shut, and that frame.
std::pair<double, int> firstLetGo(const Scene& scene, const Multimesh& mesh) {
  FrameStream stream = sceneFrameStream(scene, mesh);
  while (!stream.done()) {
    const AnimationFrame frame = stream.next();
    for (char held : frame.heldPairs)
      if (!held) return {frame.weights(1), frame.index};
  }
  return {-1, -1};
}

}  // namespace

TEST_CASE("cut timing: a cut's own release moves the frame it lets go to where the open key's weight passes it, and the "
          "scrubber's event with it") {
  Scene scene = loadScene(kChomp);
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  REQUIRE(scene.keys[0].cuts.size() == 1);
  for (double release : {0.2, 0.7}) {
    INFO("release " << release);
    scene.keys[0].cuts[0].release = release;
    scene.keys[0].cuts[0].releaseWindow = 0.2;  // glued below release - 0.1, let go above release + 0.1
    const std::vector<CutRelease> perTerm = cutReleases(scene, *built.multimesh);
    REQUIRE_FALSE(perTerm.empty());
    for (const CutRelease& t : perTerm) {
      CHECK(t.release == release);
      CHECK(t.window == 0.2);
    }
    const auto [open, frame] = firstLetGo(scene, *built.multimesh);
    INFO("lets go at frame " << frame << ", open key's weight " << open);
    CHECK(open > release - 0.1);
    CHECK(open < release + 0.1);
    const std::vector<CutEvent> events = cutEvents(scene);
    REQUIRE(events.size() == 2);  // the loop: lets go on the way to "open", glues on the way back
    CHECK(events[0].cut == "mouth");
    CHECK_FALSE(events[0].glue);
    CHECK(events[1].glue);
    const Eigen::VectorXd before = scene.timeline.weights(scene.timeline.frameTime(events[0].frame - 1));
    const Eigen::VectorXd at = scene.timeline.weights(scene.timeline.frameTime(events[0].frame));
    CHECK(before(1) < release);
    CHECK(at(1) >= release);
  }
}

TEST_CASE("cut timing: under the scene's own tau timing there are no release events, and without per-cut values no "
          "per-term timings") {
  Scene scene = loadScene(kChomp);
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  CHECK(cutReleases(scene, *built.multimesh).empty());
  CHECK(cutEvents(scene).size() == 2);
  scene.interpolation.cohesive.timing = CutTiming::kTau;
  CHECK(cutEvents(scene).empty());
}

TEST_CASE("cut timing: keys that draw the same cut with different releases are an input error naming the cut, both keys "
          "and the field") {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(std::string(INBETWEEN_ASSETS) + "/continental-drift/scene.json"));
  // rift_C is drawn in pangaea, rift and three.
  const auto cutIn = [&](int key) -> nlohmann::json& {
    for (auto& cut : j["keys"][key]["cuts"])
      if (cut["name"] == "rift_C") return cut;
    throw std::logic_error("no rift_C");
  };
  cutIn(0)["release"] = 0.3;
  cutIn(2)["release"] = 0.6;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "inbetween-cut-timing-clash";
  std::filesystem::remove_all(dir);
  std::filesystem::copy(std::string(INBETWEEN_ASSETS) + "/continental-drift", dir);
  std::ofstream((dir / "scene.json").string()) << j.dump(1);
  const std::string message = test::inputError([&] { loadScene((dir / "scene.json").string()); });
  INFO(message);
  CHECK_THAT(message, Catch::Contains("rift_C") && Catch::Contains("\"release\"") && Catch::Contains("pangaea") &&
                          Catch::Contains("three"));
  cutIn(2)["release"] = 0.3;  // the same value in both: fine
  cutIn(1)["release_window"] = 1.5;
  std::ofstream((dir / "scene.json").string()) << j.dump(1);
  const std::string outOfRange = test::inputError([&] { loadScene((dir / "scene.json").string()); });
  INFO(outOfRange);
  CHECK_THAT(outOfRange, Catch::Contains("rift_C") && Catch::Contains("release_window"));
  std::filesystem::remove_all(dir);
}
