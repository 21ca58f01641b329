// `inbetween new` and `inbetween edit --apply` (docs/editor.md): a scene started from drawings and
// built up by operations, as the editor window builds it, without typing the scene's JSON. The
// README's chomp drawings (tests/topology/chomp) are the artwork.
#include "cli_support.h"
#include "core/atomic_file.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using test::inbetween;

namespace {

const fs::path kChomp = fs::path(INBETWEEN_ASSETS) / ".." / "tests" / "topology" / "chomp";

// A folder of the scratch area with chomp's two drawings in it.
fs::path chompDrawings(const std::string& name) {
  const fs::path folder = test::scratchPath(name);
  fs::create_directories(folder);
  for (const char* file : {"closed.png", "open.png"}) fs::copy_file(kChomp / file, folder / file, fs::copy_options::overwrite_existing);
  return folder;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// The README's chomp, placed a few pixels off the outline where a click would land.
const char* kChompOps = R"([
  {"op": "add_feature", "key": "closed", "name": "top", "at": [127, 24]},
  {"op": "add_feature", "key": "open", "name": "top", "at": [129, 31]},
  {"op": "add_cut", "key": "closed", "name": "mouth", "kind": "notch", "points": [[228, 128], [128, 128]]},
  {"op": "add_feature", "key": "open", "name": "mouth.left", "at": [212, 186]},
  {"op": "add_feature", "key": "open", "name": "mouth.right", "at": [211, 69]},
  {"op": "add_feature", "key": "open", "name": "mouth.tip", "at": [126, 129]},
  {"op": "add_mark", "time": 0.5, "key": "open", "ease": "ease-in-out"}
])";

}  // namespace

TEST_CASE("cli: inbetween new writes a looping scene of its drawings, one key per file named after it, and never "
          "over a file") {
  const fs::path folder = chompDrawings("new");
  const std::string scene = (folder / "scene.json").string();
  const test::CommandRun run = inbetween({"new", scene, (folder / "closed.png").string(), (folder / "open.png").string(), "--no-window"});
  INFO(run.output);
  REQUIRE(run.code == 0);
  const ib::Scene loaded = ib::loadScene(scene);
  REQUIRE(loaded.keys.size() == 2);
  CHECK(loaded.keys[0].name == "closed");
  CHECK(loaded.keys[1].name == "open");
  CHECK(loaded.timeline.loops());
  CHECK(loaded.timeline.frameCount() == 48);  // a second per key at 24 fps, back to the first
  const std::string before = ib::readFile(scene);
  const test::CommandRun again = inbetween({"new", scene, (folder / "closed.png").string(), (folder / "open.png").string(), "--no-window"});
  CHECK(again.code == 2);
  CHECK(again.err.find("exists already") != std::string::npos);
  CHECK(ib::readFile(scene) == before);
  const test::CommandRun missing = inbetween({"new", (folder / "other.json").string(), (folder / "closed.png").string(), (folder / "nope.png").string(), "--no-window"});
  CHECK(missing.code == 2);
  CHECK(missing.err.find("nope.png") != std::string::npos);
  CHECK_FALSE(test::exists((folder / "other.json").string()));
}

TEST_CASE("cli: edit --apply builds the README's chomp from its drawings: features snapped onto the outline, a notch, "
          "a mark, and the scene meshes") {
  const fs::path folder = chompDrawings("edit-chomp");
  const std::string scene = (folder / "scene.json").string();
  REQUIRE(inbetween({"new", scene, (folder / "closed.png").string(), (folder / "open.png").string(), "--no-window"}).code == 0);
  write(folder / "ops.json", kChompOps);
  const test::CommandRun run = inbetween({"edit", scene, "--apply", (folder / "ops.json").string()});
  INFO(run.output);
  REQUIRE(run.code == 0);
  const ib::Scene edited = ib::loadScene(scene);
  // "top" was placed 4 px above the disc (its outline at y = 28, the ink's outer edge): snapped.
  const Eigen::Vector2d top = edited.keys[0].features.at("top");
  CHECK(top.y() > 25.5);
  CHECK(top.y() < 30.5);
  CHECK(std::abs(top.x() - 127) < 1.5);
  REQUIRE(edited.keys[0].cuts.size() == 1);
  CHECK(edited.keys[0].cuts[0].name == "mouth");
  CHECK(edited.timeline.marks().size() == 4);
  const test::CommandRun mesh = inbetween({"mesh", scene, "--no-pictures"});
  INFO(mesh.output);
  CHECK(mesh.code == 0);
}

TEST_CASE("cli: a bad operation exits 2 with one message naming the operation and its field, and writes nothing") {
  const fs::path folder = chompDrawings("edit-bad");
  const std::string scene = (folder / "scene.json").string();
  REQUIRE(inbetween({"new", scene, (folder / "closed.png").string(), (folder / "open.png").string(), "--no-window"}).code == 0);
  const std::string before = ib::readFile(scene);
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {R"([{"op": "add_feature", "key": "clsed", "name": "top", "at": [128, 28]}])", {"operation 0", "clsed", "closed"}},
      {R"([{"op": "add_featur", "key": "closed", "name": "top", "at": [128, 28]}])", {"operation 0", "unknown operation", "add_feature"}},
      {R"([{"op": "add_feature", "key": "closed", "name": "top", "at": [128, 28]},
           {"op": "add_feature", "key": "open", "name": "top", "at": [128, 90]}])", {"operation 1", "top", "px from key \"open\"'s outline"}},
      // A notch whose inner end lies outside the disc: the scene loads, the closed key's shape does not build.
      {R"([{"op": "add_feature", "key": "closed", "name": "top", "at": [128, 28]},
           {"op": "add_feature", "key": "open", "name": "top", "at": [128, 28]},
           {"op": "add_cut", "key": "closed", "name": "mouth", "kind": "notch", "points": [[228, 128], [250, 10]]},
           {"op": "add_feature", "key": "open", "name": "mouth.left", "at": [210, 185]},
           {"op": "add_feature", "key": "open", "name": "mouth.right", "at": [210, 71]},
           {"op": "add_feature", "key": "open", "name": "mouth.tip", "at": [128, 128]}])", {"after the operations", "mouth", "closed"}},
      {R"([{"op": "add_key", "name": "open", "drawing": "open.png"}])", {"operation 0", "open"}},
      {R"([{"op": "add_feature", "key": "closed", "name": "top"}])", {"operation 0", "field \"at\"", "missing"}},
      {R"([{"op": "add_feature", "key": "closed", "name": "top", "at": [128, 28], "radius": 3}])", {"operation 0", "field \"radius\"", "not a field"}},
      {R"({"op": "add_feature"})", {"JSON array"}},
      {R"([{"op": "add_feature", "key": "closed", "name": "top", "at": [128, 28]}])", {"after the operations", "top"}},
  };
  for (const auto& [ops, words] : cases) {
    INFO(ops);
    write(folder / "ops.json", ops);
    const std::string out = (folder / "out.json").string();
    const test::CommandRun run = inbetween({"edit", scene, "--apply", (folder / "ops.json").string(), "-o", out});
    INFO(run.output);
    CHECK(run.code == 2);
    for (const std::string& word : words) CHECK(run.err.find(word) != std::string::npos);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);  // one message
    CHECK(ib::readFile(scene) == before);
    CHECK_FALSE(test::exists(out));
  }
}
