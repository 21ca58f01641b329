// The player's live parameters (engine/playback/live_parameters.h) and saving them back into the
// scene file (engine/playback/scene_parameters.h).
#include "playback/live_parameters.h"
#include "playback/scene_parameters.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/scene.h"
#include "testkit/drawings.h"
#include "testkit/example_scenes.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

using namespace ib;
using ib::play::LiveParameters;
namespace fs = std::filesystem;

namespace {

const test::ExampleScene& example(const std::string& name) {
  static const std::vector<test::ExampleScene> all = test::goodScenes();
  for (const auto& scene : all)
    if (scene.name == name) return scene;
  throw std::logic_error("no example scene " + name);
}

Scene parsed(const std::string& name) { return parseScene(example(name).json, name + ".json"); }

// The scene `name` written to a fresh scratch folder; returns its scene file.
std::string written(const std::string& name, const std::string& folder) {
  const std::string dir = test::scratchDirectory(folder);
  test::writeScene(example(name), dir);
  return (fs::path(dir) / name / "scene.json").string();
}

// The message of the InputError `f` throws ("" when it throws none).
template <typename F>
std::string inputError(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

using Json = nlohmann::ordered_json;

// The scene file's JSON without the fields saveParameters writes (and without sections it may
// have added that are then empty).
Json withoutSaved(Json j) {
  const std::vector<std::pair<const char*, std::vector<const char*>>> saved = {
      {"solver", {"tau", "alpha", "lambda", "non_overlap", "kappa"}},
      {"dynamics", {"epsilon", "mu", "gravity", "wind", "anchor"}},
      {"timeline", {"fps"}},
      {"stiffness", {"range"}},
  };
  for (const auto& [section, fields] : saved) {
    if (!j.contains(section)) continue;
    for (const char* field : fields) j[section].erase(field);
    if (j[section].empty()) j.erase(section);
  }
  if (j.contains("stiffness") && j["stiffness"].contains("regions"))
    for (Json& region : j["stiffness"]["regions"]) region.erase("kappa");
  return j;
}

Json readJson(const std::string& path) { return Json::parse(readFile(path)); }

}  // namespace

TEST_CASE("live parameters: they start from the scene's values, each its own default") {
  const Scene scene = parsed("square-arch-stretch");
  const LiveParameters p(scene);
  CHECK(p.get("tau") == scene.solver.tau);
  CHECK(p.get("alpha") == scene.solver.alpha);
  CHECK(p.get("lambda") == scene.solver.lambda);
  CHECK(p.get("non_overlap") == 0);
  CHECK(p.get("kappa_scale") == 1);
  CHECK(p.get("dynamics") == 1);  // epsilon 0.6 > 0
  CHECK(p.get("epsilon") == 0.6);
  CHECK(p.get("mu") == 1);
  CHECK(p.get("gravity_y") == 3);
  CHECK(p.get("anchor") == scene.dynamics.anchor);
  const std::vector<std::string> names = {"tau", "alpha", "lambda", "kappa_scale", "non_overlap", "dynamics", "epsilon",
                                          "mu", "gravity_x", "gravity_y", "wind_x", "wind_y", "anchor"};
  REQUIRE(p.all().size() == names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    const auto& parameter = p.all()[i];
    CHECK(parameter.name == names[i]);
    CHECK(parameter.value == parameter.initial);
    CHECK(parameter.min <= parameter.value);
    CHECK(parameter.value <= parameter.max);
    CHECK_FALSE(parameter.help.empty());
    if (parameter.logScale) CHECK(parameter.min > 0);
  }
  CHECK(p.generation() == 0);
}

TEST_CASE("live parameters: dynamics start off for a scene without them, and off means epsilon 0") {
  LiveParameters p(parsed("square-arch-notch"));
  CHECK(p.get("dynamics") == 0);
  CHECK(p.dynamics().epsilon == 0);
  p.set("dynamics", 1);
  CHECK(p.dynamics().epsilon == p.get("epsilon"));
  CHECK(p.dynamics().epsilon > 0);
}

TEST_CASE("live parameters: a slider's range widens to hold a scene value outside it") {
  Scene scene = parsed("square-arch-notch");
  scene.solver.tau = 5;
  scene.dynamics.mu = 50;
  LiveParameters p(scene);
  CHECK(p.all()[0].max == 5);
  CHECK(p.get("tau") == 5);
  CHECK(p.get("mu") == 50);
  p.set("tau", 2);
  p.set("mu", 30);
  CHECK_FALSE(inputError([&] { p.set("tau", 6); }).empty());
}

TEST_CASE("live parameters: set, get and reset change one value and bump the generation on every change") {
  LiveParameters p(parsed("square-arch-stretch"));
  p.set("tau", 1e-4);
  CHECK(p.get("tau") == 1e-4);
  CHECK(p.generation() == 1);
  p.set("tau", 1e-4);  // the same value: no change
  CHECK(p.generation() == 1);
  p.set("wind_x", -2);
  CHECK(p.generation() == 2);
  p.reset("tau");
  CHECK(p.get("tau") == p.all()[0].initial);
  CHECK(p.generation() == 3);
  p.set("lambda", 1e5);
  p.set("non_overlap", 1);
  p.resetAll();
  for (const auto& parameter : p.all()) CHECK(parameter.value == parameter.initial);
  CHECK(p.generation() == 8);  // resetAll: wind_x, lambda, non_overlap
}

TEST_CASE("live parameters: unknown names, out-of-range and non-finite values are input errors naming the parameter and its range") {
  LiveParameters p(parsed("square-arch-stretch"));
  CHECK_THAT(inputError([&] { p.set("tao", 1); }), Catch::Contains("\"tao\"") && Catch::Contains("tau"));
  CHECK_THAT(inputError([&] { p.get("kappa"); }), Catch::Contains("\"kappa\""));
  CHECK_THAT(inputError([&] { p.set("alpha", 1.5); }), Catch::Contains("\"alpha\"") && Catch::Contains("[0, 1]"));
  CHECK_THAT(inputError([&] { p.set("tau", 0); }), Catch::Contains("\"tau\"") && Catch::Contains("[1e-06, 1]"));
  CHECK_THAT(inputError([&] { p.set("mu", std::numeric_limits<double>::infinity()); }), Catch::Contains("\"mu\""));
  CHECK_THAT(inputError([&] { p.set("lambda", std::nan("")); }), Catch::Contains("\"lambda\""));
  CHECK_THAT(inputError([&] { p.set("dynamics", 0.5); }), Catch::Contains("\"dynamics\"") && Catch::Contains("0 (off) or 1"));
  CHECK(p.generation() == 0);
  CHECK(p.get("alpha") == 0.5);
}

TEST_CASE("live parameters: interpolation() and dynamics() carry the current values") {
  LiveParameters p(parsed("square-arch-stretch"));
  p.set("tau", 2e-4);
  p.set("alpha", 0.25);
  p.set("lambda", 8000);
  p.set("non_overlap", 1);
  p.set("epsilon", 0.3);
  p.set("mu", 2.5);
  p.set("gravity_x", 1);
  p.set("gravity_y", -2);
  p.set("wind_x", 0.5);
  p.set("wind_y", 0.25);
  p.set("anchor", 0.4);
  p.set("kappa_scale", 3);
  const InterpolationParams i = p.interpolation();
  CHECK(i.cohesive.tau == 2e-4);
  CHECK(i.cohesive.alpha == 0.25);
  CHECK(i.cohesive.lambda == 8000);
  CHECK(i.nonOverlap);
  const DynamicsParams d = p.dynamics();
  CHECK(d.epsilon == 0.3);
  CHECK(d.mu == 2.5);
  CHECK(d.gravity == Eigen::Vector2d(1, -2));
  CHECK(d.wind == Eigen::Vector2d(0.5, 0.25));
  CHECK(d.anchor == 0.4);
  CHECK(d.settle == DynamicsParams{}.settle);  // the fields without a slider are the scene's
  CHECK(p.kappaScale() == 3);
  p.set("dynamics", 0);
  CHECK(p.dynamics().epsilon == 0);
  CHECK(p.dynamics().mu == 2.5);
}

TEST_CASE("live parameters: setFromText parses NAME=VALUE and names the text when it cannot") {
  LiveParameters p(parsed("square-arch-notch"));
  p.setFromText("tau=1e-5");
  CHECK(p.get("tau") == 1e-5);
  p.setFromText("non_overlap=on");
  CHECK(p.get("non_overlap") == 1);
  p.setFromText("dynamics=1");
  CHECK(p.get("dynamics") == 1);
  CHECK_THAT(inputError([&] { p.setFromText("tau"); }), Catch::Contains("\"tau\""));
  CHECK_THAT(inputError([&] { p.setFromText("tau=abc"); }), Catch::Contains("tau=abc") && Catch::Contains("not a number"));
  CHECK_THAT(inputError([&] { p.setFromText("tau=1e-3x"); }), Catch::Contains("tau=1e-3x"));
  CHECK_THAT(inputError([&] { p.setFromText("size=3"); }), Catch::Contains("size=3") && Catch::Contains("unknown"));
  CHECK_THAT(inputError([&] { p.setFromText("alpha=2"); }), Catch::Contains("alpha=2") && Catch::Contains("[0, 1]"));
}

TEST_CASE("saveParameters: saved parameters load back as tuned, every other field and the key order unchanged") {
  for (const std::string name : {"square-arch-stretch", "square-arch-notch"}) {
    DYNAMIC_SECTION(name) {
      const std::string file = written(name, "save-" + name);
      const Scene scene = loadScene(file);
      const Json before = readJson(file);
      LiveParameters p(scene);
      p.set("tau", 1e-4);
      p.set("alpha", 0.3);
      p.set("lambda", 16000);
      p.set("non_overlap", 1);
      p.set("dynamics", 1);
      p.set("epsilon", 0.8);
      p.set("mu", 2);
      p.set("gravity_x", 0.5);
      p.set("gravity_y", 4);
      p.set("wind_x", 1);
      p.set("anchor", 0.2);
      p.set("kappa_scale", 2);
      play::saveParameters(file, p, 30);

      const Scene saved = loadScene(file);
      CHECK(saved.solver.tau == 1e-4);
      CHECK(saved.solver.alpha == 0.3);
      CHECK(saved.solver.lambda == 16000);
      CHECK(saved.solver.nonOverlap);
      CHECK(saved.solver.kappa == 2 * scene.solver.kappa);
      REQUIRE(saved.stiffness.regions.size() == scene.stiffness.regions.size());
      for (size_t r = 0; r < saved.stiffness.regions.size(); ++r)
        CHECK(saved.stiffness.regions[r].kappa == 2 * scene.stiffness.regions[r].kappa);
      CHECK(saved.dynamics.epsilon == 0.8);
      CHECK(saved.dynamics.mu == 2);
      CHECK(saved.dynamics.gravity == Eigen::Vector2d(0.5, 4));
      CHECK(saved.dynamics.wind == Eigen::Vector2d(1, 0));
      CHECK(saved.dynamics.anchor == 0.2);
      CHECK(saved.timeline.fps() == 30);
      CHECK(LiveParameters(saved).get("kappa_scale") == 1);

      // Everything else, key order included (ordered JSON dumps in file order).
      CHECK(withoutSaved(readJson(file)).dump() == withoutSaved(before).dump());
      for (const auto& entry : fs::directory_iterator(fs::path(file).parent_path()))
        CHECK(entry.path().filename().string().find(".tmp") == std::string::npos);
    }
  }
}

TEST_CASE("saveParameters: saving untouched parameters leaves every field of the scene file as it was") {
  const std::string file = written("square-arch-stretch", "save-untouched");
  const Json before = readJson(file);
  play::saveParameters(file, LiveParameters(loadScene(file)), 24);
  CHECK(readJson(file) == before);
  CHECK(readJson(file).dump() == before.dump());
}

TEST_CASE("saveParameters: saving with dynamics off writes epsilon 0") {
  const std::string file = written("square-arch-stretch", "save-off");
  LiveParameters p(loadScene(file));
  p.set("dynamics", 0);
  play::saveParameters(file, p, 24);
  CHECK(loadScene(file).dynamics.epsilon == 0);
  CHECK(loadScene(file).dynamics.mu == 1);
}

TEST_CASE("saveParameters: kappa_scale scales a painted image's stiffness range, from the default range when absent") {
  const std::string file = written("square-arch-notch", "save-range");
  Json j = readJson(file);
  j["stiffness"] = {{"image", {{"key", "square"}, {"path", "square.png"}}}};
  writeFileAtomically(file, j.dump(2));
  LiveParameters p(loadScene(file));
  p.set("kappa_scale", 0.5);
  play::saveParameters(file, p, 24);
  const Scene saved = loadScene(file);
  CHECK(saved.stiffness.soft == Approx(0.05).epsilon(1e-12));
  CHECK(saved.stiffness.stiff == Approx(5).epsilon(1e-12));
  CHECK(saved.solver.kappa == 0.5);
}

TEST_CASE("saveParameters: a scene file that cannot be written is an input error naming it, and the old file stays") {
  const std::string dir = test::scratchDirectory("save-unwritable");
  const std::string good = written("square-arch-notch", "save-unwritable-source");
  const std::string text = readFile(good);
  // 250 characters: the file itself can exist, the temporary file beside it cannot (NAME_MAX 255).
  const std::string file = (fs::path(dir) / (std::string(245, 's') + ".json")).string();
  {
    std::ofstream out(file, std::ios::binary);
    out << text;
  }
  REQUIRE(readFile(file) == text);
  LiveParameters p(loadScene(good));
  p.set("tau", 1e-4);
  CHECK_THAT(inputError([&] { play::saveParameters(file, p, 24); }), Catch::Contains(file));
  CHECK(readFile(file) == text);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);

  const std::string missing = (fs::path(dir) / "missing.json").string();
  CHECK_THAT(inputError([&] { play::saveParameters(missing, p, 24); }), Catch::Contains(missing));
  CHECK_FALSE(fs::exists(missing));
}
