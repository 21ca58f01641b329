// Cut timing (docs/scene-format.md, "Cut timing"): a cut's own release moves when it lets go, the
// scrubber's events fall where the weights cross it, and the keys that draw a cut agree on it;
// under tau a smaller tau never lets go later; on the drawn topology scenes nothing pops.
#include "animation/frame_changes.h"
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

TEST_CASE("cut timing tau: a larger tau never lets a cut go earlier, and a cut that lets go does so as one and stays "
          "apart while the timeline goes on") {
  // drop-split (hang -> neck -> split, the neck's cut closed in hang and neck): the timeline only
  // moves on, so a cut that let go stays apart to the end.
  Scene scene = loadScene(std::string(INBETWEEN_SOURCE_DIR) + "/tests/topology/drop-split/scene.json");
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  const Multimesh& mesh = *built.multimesh;
  std::vector<int> keyOfTerm;  // heldPairs' order: key 0's pairs, then key 1's, ...
  for (int k = 0; k < mesh.keyCount(); ++k) keyOfTerm.insert(keyOfTerm.end(), mesh.cohesivePairs(k).size(), k);
  scene.interpolation.cohesive.timing = CutTiming::kTau;
  int previous = -1;
  std::vector<int> letGoFrames;
  for (double tau : {5e-8, 1e-7, 3e-7, 1e-6, 1e-5}) {
    INFO("tau " << tau);
    scene.interpolation.cohesive.tau = tau;
    FrameStream stream = sceneFrameStream(scene, mesh);
    int letGo = -1, heldAfter = 0;
    while (!stream.done()) {
      const AnimationFrame frame = stream.next();
      REQUIRE(frame.heldPairs.size() == keyOfTerm.size());
      int held = 0, weighted = 0;
      for (size_t j = 0; j < keyOfTerm.size(); ++j)
        if (frame.weights(keyOfTerm[j]) > 0) ++weighted, held += frame.heldPairs[j];
      if (letGo < 0 && held < weighted) letGo = frame.index;
      // From the frame after it let go on (the frame itself shows the pairs that passed tau), none holds.
      else if (letGo >= 0) heldAfter += held;
    }
    letGoFrames.push_back(letGo);
    CHECK(letGo >= 0);
    CHECK(heldAfter == 0);
    CHECK(letGo >= previous);
    previous = letGo;
  }
  INFO("let go at frames " << letGoFrames[0] << " .. " << letGoFrames.back());
  CHECK(letGoFrames.front() < letGoFrames.back());
}

TEST_CASE("cut timing: on every drawn topology scene no step where a cut lets go or glues jumps, and glued shapes keep "
          "their area") {
  // tests/topology: a drop splitting, a disc opening its mouth, two blobs merging, a ring opening,
  // letters of a real font (l -> i, O -> C), inked as drawn. A jump is a step that changes both more
  // than 2.6 times its segment's median step and more than 2% of the silhouette (a step of 1% is
  // a few pixels of a letter's edge, where the median itself is rasterization noise). Before cut
  // timing, drop-split's split changed 42% of the silhouette in one step (26x the median).
  const std::filesystem::path topology = std::filesystem::path(INBETWEEN_SOURCE_DIR) / "tests" / "topology";
  int scenes = 0, events = 0;
  for (const auto& entry : std::filesystem::directory_iterator(topology)) {
    if (!std::filesystem::exists(entry.path() / "scene.json")) continue;
    INFO(entry.path().filename().string());
    ++scenes;
    const Scene scene = loadScene((entry.path() / "scene.json").string());
    const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
    FrameStream stream = sceneFrameStream(scene, *built.multimesh);
    std::vector<AnimationFrame> frames;
    while (!stream.done()) frames.push_back(stream.next());
    for (const SegmentChanges& segment : segmentChanges(*built.multimesh, scene.timeline, frames)) {
      INFO("segment " << segment.segment << ": largest step " << segment.maxPixels << " px at frame "
                      << segment.maxPixelsFrame << " (" << 100 * segment.maxPixelsShare << "% of the silhouette), median "
                      << segment.medianPixels << " px; smallest area ratio " << segment.minAreaRatio);
      CHECK(segment.minAreaRatio >= 0.96);
      if (segment.releases.empty() && segment.glues.empty()) continue;
      ++events;
      CHECK((segment.maxPixels <= 2.6 * segment.medianPixels || segment.maxPixelsShare <= 0.02));
    }
  }
  CHECK(scenes >= 6);
  CHECK(events >= 6);
}
