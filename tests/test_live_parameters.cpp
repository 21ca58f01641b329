// The player's live parameters (engine/playback/live_parameters.h) and saving them back into the
// scene file (engine/playback/scene_parameters.h).
#include <algorithm>
#include "playback/live_parameters.h"
#include "playback/scene_parameters.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "scene/parameters.h"
#include "scene/scene.h"
#include "testkit/drawings.h"
#include "testkit/errors.h"
#include "testkit/example_scenes.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

using namespace ib;
using ib::play::LiveParameters;
namespace fs = std::filesystem;

using ::test::inputError;

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
  CHECK(p.get("tau") == scene.interpolation.cohesive.tau);
  CHECK(p.get("alpha") == scene.interpolation.cohesive.alpha);
  CHECK(p.get("lambda") == scene.interpolation.cohesive.lambda);
  CHECK(p.get("non_overlap") == 0);
  CHECK(p.get("metric") == 0);  // shared
  CHECK(p.get("kappa_scale") == 1);
  CHECK(p.get("dynamics") == 1);  // epsilon 0.6 > 0
  CHECK(p.get("epsilon") == 0.6);
  CHECK(p.get("mu") == 1);
  CHECK(p.get("gravity_y") == 3);
  CHECK(p.get("anchor") == scene.dynamics.anchor);
  // One control per live row of the table, in its order.
  std::vector<std::string> live;
  for (const ParameterSpec& spec : parameterTable())
    if (spec.live) live.push_back(spec.name);
  REQUIRE(p.all().size() == live.size());
  for (size_t i = 0; i < live.size(); ++i) {
    const play::Control& c = p.all()[i];
    CHECK(c.spec->name == live[i]);
    CHECK(c.value == c.initial);
    CHECK_FALSE(c.spec->meaning.empty());
  }
  CHECK(p.generation() == 0);
}

TEST_CASE("live parameters: a slider covers every value the scene file takes, typed entry the rest of an open range") {
  const LiveParameters p(parsed("square-arch-notch"));
  for (const play::Control& c : p.all()) {
    const ParameterSpec& spec = *c.spec;
    if (spec.kind != ParameterKind::kNumber) continue;
    INFO(spec.name);
    const double lowest = c.scale.fromSlider(c.sliderMin), highest = c.scale.fromSlider(c.sliderMax);
    CHECK(highest >= spec.max * (1 - 1e-12));
    if (!spec.minOpen) CHECK(lowest <= spec.min + 1e-12 * std::abs(spec.min));
    else if (spec.logScale) CHECK(lowest <= 1e-12 * (1 + 1e-9));  // tau 1e-9 (bundled scenes) is on the slider
    else CHECK(lowest <= spec.min + 1e-3 * (spec.max - spec.min));
    // The slider's scale maps back and forth, and moves the same way as the value.
    for (int k = 0; k <= 8; ++k) {
      const double s = c.sliderMin + k * (c.sliderMax - c.sliderMin) / 8;
      CHECK(c.scale.toSlider(c.scale.fromSlider(s)) == Approx(s).margin(1e-9));
      if (k > 0) CHECK(c.scale.fromSlider(s) > c.scale.fromSlider(s - (c.sliderMax - c.sliderMin) / 8));
    }
  }
  // tau down to the smallest value the file takes, through --set as through a typed entry.
  LiveParameters q(parsed("square-arch-notch"));
  q.setFromText("tau=1e-9");
  CHECK(q.get("tau") == 1e-9);
  q.setFromText("tau=1e-300");
  CHECK(q.get("tau") == 1e-300);
  q.setFromText("tau=1e6");
  CHECK(q.get("tau") == 1e6);
  q.setFromText("lambda=0");
  CHECK(q.get("lambda") == 0);
  q.setFromText("mu=1e6");
  CHECK(q.get("mu") == 1e6);
}

TEST_CASE("live parameters: the metric plays as the scene asks, and as the player sets it") {
  Scene scene = parsed("square-arch-stretch");
  scene.interpolation.metric = ShapeMetric::kPerKey;
  LiveParameters p(scene);
  CHECK(p.get("metric") == 1);
  CHECK(p.scene(scene).interpolation.metric == ShapeMetric::kPerKey);
  p.setFromText("metric=shared");
  CHECK(p.scene(scene).interpolation.metric == ShapeMetric::kShared);
}

TEST_CASE("live parameters: dynamics start off for a scene without them, and off means epsilon 0") {
  const Scene scene = parsed("square-arch-notch");
  LiveParameters p(scene);
  CHECK(p.get("dynamics") == 0);
  CHECK_FALSE(p.frameOptions().dynamics);
  p.set("dynamics", 1);
  CHECK(p.frameOptions().dynamics);
  CHECK(p.scene(scene).dynamics.epsilon == p.get("epsilon"));
  CHECK(p.get("epsilon") > 0);
}

TEST_CASE("live parameters: a slider's range widens to hold a scene value outside it") {
  Scene scene = parsed("square-arch-notch");
  scene.interpolation.cohesive.tau = 1e-14;
  LiveParameters p(scene);
  const auto tau = std::find_if(p.all().begin(), p.all().end(), [](const play::Control& c) { return c.spec->name == "tau"; });
  REQUIRE(tau != p.all().end());
  CHECK(tau->scale.fromSlider(tau->sliderMin) == Approx(1e-14));
  CHECK(p.get("tau") == 1e-14);
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
  CHECK(p.get("tau") == parsed("square-arch-stretch").interpolation.cohesive.tau);
  CHECK(p.generation() == 3);
  p.set("lambda", 1e5);
  p.set("non_overlap", 1);
  p.resetAll();
  for (const play::Control& c : p.all()) CHECK(c.value == c.initial);
  CHECK(p.generation() == 8);  // resetAll: wind_x, lambda, non_overlap
}

TEST_CASE("live parameters: unknown names, values out of the file's range and non-finite values are input errors naming the parameter and its range") {
  LiveParameters p(parsed("square-arch-stretch"));
  CHECK_THAT(inputError([&] { p.set("tao", 1); }), Catch::Contains("\"tao\"") && Catch::Contains("did you mean \"tau\""));
  CHECK_THAT(inputError([&] { p.get("edge_length"); }),
             Catch::Contains("\"edge_length\"") && Catch::Contains("changes the multimesh") && Catch::Contains("render --set"));
  CHECK_THAT(inputError([&] { p.set("alpha", 1.5); }), Catch::Contains("\"alpha\"") && Catch::Contains("[0, 1]"));
  CHECK_THAT(inputError([&] { p.set("tau", 0); }), Catch::Contains("\"tau\"") && Catch::Contains("(0, 1e+06]"));
  CHECK_THAT(inputError([&] { p.set("mu", std::numeric_limits<double>::infinity()); }), Catch::Contains("\"mu\""));
  CHECK_THAT(inputError([&] { p.set("lambda", std::nan("")); }), Catch::Contains("\"lambda\""));
  CHECK_THAT(inputError([&] { p.set("dynamics", 0.5); }), Catch::Contains("\"dynamics\"") && Catch::Contains("on or off"));
  CHECK(p.generation() == 0);
  CHECK(p.get("alpha") == 0.5);
}

TEST_CASE("live parameters: scene() and frameOptions() carry the current values through the one mapping") {
  const Scene base = parsed("square-arch-stretch");
  LiveParameters p(base);
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
  p.set("settle", 0.5);
  p.set("kappa_scale", 3);
  const Scene s = p.scene(base);
  CHECK(s.interpolation.cohesive.tau == 2e-4);
  CHECK(s.interpolation.cohesive.alpha == 0.25);
  CHECK(s.interpolation.cohesive.lambda == 8000);
  CHECK(s.interpolation.nonOverlap);
  CHECK(s.dynamics.epsilon == 0.3);
  CHECK(s.dynamics.mu == 2.5);
  CHECK(s.dynamics.gravity == Eigen::Vector2d(1, -2));
  CHECK(s.dynamics.wind == Eigen::Vector2d(0.5, 0.25));
  CHECK(s.dynamics.anchor == 0.4);
  CHECK(s.dynamics.settle == 0.5);
  CHECK(p.frameOptions().kappaScale == 3);
  p.set("dynamics", 0);
  CHECK_FALSE(p.frameOptions().dynamics);
  CHECK(p.scene(base).dynamics.mu == 2.5);
}

TEST_CASE("live parameters: setFromText parses NAME=VALUE and names the text when it cannot") {
  LiveParameters p(parsed("square-arch-notch"));
  p.setFromText("tau=1e-5");
  CHECK(p.get("tau") == 1e-5);
  p.setFromText("non_overlap=on");
  CHECK(p.get("non_overlap") == 1);
  p.setFromText("dynamics=1");
  CHECK(p.get("dynamics") == 1);
  p.setFromText("solver.alpha=0.75");  // the field's name works too
  CHECK(p.get("alpha") == 0.75);
  CHECK_THAT(inputError([&] { p.setFromText("tau"); }), Catch::Contains("\"tau\""));
  CHECK_THAT(inputError([&] { p.setFromText("tau=abc"); }), Catch::Contains("tau=abc") && Catch::Contains("not a number"));
  CHECK_THAT(inputError([&] { p.setFromText("tau=1e-3x"); }), Catch::Contains("tau=1e-3x"));
  CHECK_THAT(inputError([&] { p.setFromText("size=3"); }), Catch::Contains("size=3") && Catch::Contains("unknown"));
  CHECK_THAT(inputError([&] { p.setFromText("alpha=2"); }), Catch::Contains("alpha=2") && Catch::Contains("[0, 1]"));
  CHECK_THAT(inputError([&] { p.setFromText("metric=perkey"); }),
             Catch::Contains("metric=perkey") && Catch::Contains("did you mean \"per_key\""));
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
      CHECK(saved.interpolation.cohesive.tau == 1e-4);
      CHECK(saved.interpolation.cohesive.alpha == 0.3);
      CHECK(saved.interpolation.cohesive.lambda == 16000);
      CHECK(saved.interpolation.nonOverlap);
      CHECK(saved.kappa == 2 * scene.kappa);
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
  LiveParameters untouched(loadScene(file));
  play::saveParameters(file, untouched, 24);
  CHECK(readJson(file) == before);
  CHECK(readJson(file).dump() == before.dump());
}

TEST_CASE("saveParameters: saving twice before the scene is reloaded scales the stiffness once") {
  const std::string file = written("square-arch-stretch", "save-twice");
  const Scene scene = loadScene(file);
  LiveParameters p(scene);
  p.set("kappa_scale", 2);
  play::saveParameters(file, p, 24);
  play::saveParameters(file, p, 24);
  CHECK(loadScene(file).kappa == 2 * scene.kappa);
  CHECK(loadScene(file).stiffness.regions.at(0).kappa == 2 * scene.stiffness.regions.at(0).kappa);
  p.set("kappa_scale", 3);  // moved again: scaled by what it moved since
  play::saveParameters(file, p, 24);
  CHECK(loadScene(file).kappa == Approx(3 * scene.kappa));
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
  CHECK(saved.kappa == 0.5);
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
