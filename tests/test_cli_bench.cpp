// `inbetween bench CASE` on small cases: every stdout line is one JSON object with "bench" (the
// case) and "arch" (the instruction set the command was built for), one line per case the options
// ask for, with the fields the case's --help documents (apps/bench/bench_CASE.cpp) and positive
// times.
#include "cli_support.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

using Catch::Contains;
using test::CommandRun;
using test::inbetween;
using test::jsonLines;
using Json = nlohmann::json;

namespace {

// The lines of a run that must succeed, each checked to be case `bench` built for INBETWEEN_ARCH.
std::vector<Json> benchLines(const std::vector<std::string>& args) {
  const CommandRun run = inbetween(args);
  INFO(run.output);
  REQUIRE(run.code == 0);
  const std::vector<Json> lines = jsonLines(run.out);
  for (const Json& line : lines) {
    INFO(line.dump());
    CHECK(line.at("bench") == args.at(1));
    CHECK(line.at("arch") == INBETWEEN_ARCH);
  }
  return lines;
}

// The folder names of the bundled scenes (INBETWEEN_ASSETS/NAME/scene.json), sorted.
std::vector<std::string> bundledScenes() {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(INBETWEEN_ASSETS))
    if (std::filesystem::exists(entry.path() / "scene.json")) names.insert(entry.path().filename().string());
  return {names.begin(), names.end()};
}

}  // namespace

TEST_CASE("cli: bench interp prints a JSON line per case") {
  // One size and one key count: one case, of about 300 vertices and 2 keys, 3 frames.
  const std::vector<Json> lines = benchLines({"bench", "interp", "--sizes", "300", "--keys", "2", "--frames", "3", "--no-baseline"});
  REQUIRE(lines.size() == 1);
  const Json& line = lines[0];
  INFO(line.dump());
  CHECK(line.at("vertices").get<int>() >= 250);
  CHECK(line.at("vertices").get<int>() <= 400);
  CHECK(line.at("keys") == 2);
  CHECK(line.at("frames") == 3);
  CHECK(line.at("repeats") == 3);  // the default
  CHECK(line.at("threads").get<int>() >= 1);
  CHECK(line.at("ms_per_iter").get<double>() > 0);
  CHECK(line.at("ms_per_frame").get<double>() > 0);
  CHECK(line.at("iters_to_converge").get<double>() > 0);
  // The yardstick timed beside every case, and the time relative to it.
  CHECK(line.at("reference_ms_per_iter").get<double>() > 0);
  CHECK(line.at("iter_vs_reference").get<double>() > 0);
  CHECK(line.at("unconverged_frames") == 0);
  // --no-baseline: no plain local-global comparison.
  CHECK_FALSE(line.contains("plain_iters_to_energy_1e-3"));
}

TEST_CASE("cli: bench lines report the instruction set the command was built for") {
  const std::vector<Json> lines =
      benchLines({"bench", "interp", "--sizes", "300", "--keys", "2", "--frames", "2", "--repeats", "1", "--no-baseline"});
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].at("arch") == INBETWEEN_ARCH);
  CHECK(std::string(INBETWEEN_ARCH) != "");
  CHECK(lines[0].at("repeats") == 1);
  CHECK(lines[0].at("frames") == 2);
}

TEST_CASE("cli: bench comesh prints a JSON line per case") {
  // One square-hexagon size and one star-sequence key count: two cases, in that order.
  const std::vector<Json> lines = benchLines({"bench", "comesh", "--sizes", "300", "--keys", "2"});
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].at("scene") == "square-hexagon@300");
  CHECK(lines[0].at("vertices_in").get<int>() >= 250);
  CHECK(lines[0].at("vertices_in").get<int>() <= 400);
  CHECK(lines[1].at("scene") == "star-sequence@2");
  for (const Json& line : lines) {
    INFO(line.dump());
    CHECK(line.at("keys") == 2);
    CHECK(line.at("vertices_out").get<int>() > 0);
    CHECK(line.at("outer").get<int>() > 0);
    CHECK(line.at("inner").get<int>() >= line.at("outer").get<int>());
    CHECK(line.at("seconds").get<double>() > 0);
    CHECK(line.at("build_seconds").get<double>() > 0);
    CHECK(line.at("energy_in").get<double>() > 0);
    CHECK(line.at("energy_out").get<double>() > 0);
  }
}

TEST_CASE("cli: bench anim prints a JSON line per bundled scene") {
  const std::vector<Json> lines = benchLines({"bench", "anim"});
  const std::vector<std::string> scenes = bundledScenes();
  REQUIRE(lines.size() == scenes.size());
  for (size_t i = 0; i < lines.size(); ++i) {
    const Json& line = lines[i];
    INFO(line.dump());
    CHECK(line.at("scene") == scenes[i]);  // sorted by folder name
    CHECK(line.at("vertices").get<int>() > 0);
    CHECK(line.at("keys").get<int>() >= 1);
    CHECK(line.at("frames").get<int>() > 0);
    CHECK(line.at("dynamics").is_boolean());
    CHECK(line.at("ms_per_frame").get<double>() > 0);
    CHECK(line.at("max_ms_per_frame").get<double>() >= line.at("ms_per_frame").get<double>());
    CHECK(line.at("iterations_per_frame").get<double>() >= 0);
    CHECK(line.at("converged").get<double>() >= 0);
    CHECK(line.at("converged").get<double>() <= 1);
    CHECK(line.at("max_deviation").get<double>() >= 0);
  }
}

TEST_CASE("cli: bench cut prints a JSON line per size and factor mode") {
  // One size: a line with rank-one updates of the factor, then one without.
  const std::vector<Json> lines = benchLines({"bench", "cut", "--sizes", "100", "--frames", "10", "--repeats", "1"});
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].at("update_factor") == true);
  CHECK(lines[1].at("update_factor") == false);
  for (const Json& line : lines) {
    INFO(line.dump());
    CHECK(line.at("vertices").get<int>() >= 80);
    CHECK(line.at("vertices").get<int>() <= 120);
    CHECK(line.at("pairs").get<int>() > 0);
    CHECK(line.at("frames") == 10);
    CHECK(line.at("ms_per_frame").get<double>() > 0);
    CHECK(line.at("hardest_frame").get<int>() >= 1);
    CHECK(line.at("hardest_frame").get<int>() <= 10);
    CHECK(line.at("hardest_frame_iterations").get<int>() > 0);
    CHECK(line.at("hardest_frame_ms").get<double>() > 0);
    CHECK(line.at("iterations_per_frame").get<double>() > 0);
    CHECK(line.at("factorizations").get<int>() >= 1);
  }
}

TEST_CASE("cli: bench shape prints a JSON line per scene and metric") {
  const std::vector<Json> lines = benchLines({"bench", "shape", "--scene", std::string(INBETWEEN_ASSETS) + "/square-arch-stretch/scene.json",
                                              "--no-comesh", "--steps", "8"});
  // One scene, both metrics (the default), shared first.
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].at("metric") == "shared");
  CHECK(lines[1].at("metric") == "per_key");
  for (const Json& line : lines) {
    INFO(line.dump());
    CHECK(line.at("scene") == "square-arch-stretch");
    CHECK(line.at("spacing") == "weights");
    CHECK(line.at("steps") == 8);
    CHECK(line.at("vertices").get<int>() > 0);
    CHECK(line.at("segments").get<int>() >= 1);
    CHECK(line.at("min_area_ratio").get<double>() > 0);
    CHECK(line.at("max_snap").get<double>() > 0);
    CHECK(line.at("max_retime") == 0.0);  // weights spacing moves no pose in time
    CHECK(line.at("iterations_per_step").get<double>() > 0);
    CHECK(line.at("converged").get<double>() > 0);
    CHECK(line.at("converged").get<double>() <= 1);
    CHECK(line.at("seconds").get<double>() > 0);
  }
}

TEST_CASE("cli: bench pops prints a JSON line per moving segment, and finds square-arch-notch's notch letting go") {
  const std::vector<Json> lines = benchLines({"bench", "pops", "--scenes", "square-arch-notch"});
  // Two segments (square -> arch -> square), the notch opening on the way out, glued on the way back.
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].at("from") == "square");
  CHECK(lines[0].at("to") == "arch");
  CHECK(lines[1].at("from") == "arch");
  CHECK(lines[1].at("to") == "square");
  CHECK_FALSE(lines[0].at("releases").empty());
  CHECK_FALSE(lines[1].at("glues").empty());
  for (const Json& line : lines) {
    INFO(line.dump());
    CHECK(line.at("scene") == "square-arch-notch");
    CHECK(line.at("cuts") == 1);
    CHECK(line.at("steps") == 24);
    CHECK(line.at("pop").get<double>() >= 1);
    CHECK(line.at("rms_pop").get<double>() >= 1);
    CHECK(line.at("pop_share").get<double>() > 0);
    CHECK(line.at("min_area_ratio").get<double>() > 0.5);
    CHECK(line.at("min_area_ratio").get<double>() <= 1.001);
    CHECK(line.at("pixel_steps").size() == 24);
    CHECK(line.at("rms_steps").size() == 24);
  }
}

TEST_CASE("cli: bench examples prints the paper's two tables for one example") {
  const std::vector<Json> lines = benchLines({"bench", "examples", "--only", "walk-star"});
  REQUIRE(lines.size() == 2);
  // Table 2: Comesh Optimization's row, beside the paper's.
  const Json& comesh = lines[0];
  INFO(comesh.dump());
  CHECK(comesh.at("table") == 2);
  CHECK(comesh.at("scene") == "walk-star");
  CHECK(comesh.at("keys") == 8);
  for (const char* count : {"vertices_in", "vertices_out", "triangles_in", "triangles_out", "inner", "outer"})
    CHECK(comesh.at(count).get<int>() > 0);
  CHECK(comesh.at("seconds").get<double>() > 0);
  CHECK(comesh.at("flip_seconds").get<double>() >= 0);
  CHECK(comesh.at("paper").at("name") == "walk star");
  CHECK(comesh.at("paper").at("keys") == 8);
  CHECK(comesh.at("faster").is_boolean());
  // Table 3: the animation's row on the optimized multimesh, beside the paper's.
  const Json& animation = lines[1];
  INFO(animation.dump());
  CHECK(animation.at("table") == 3);
  CHECK(animation.at("scene") == "walk-star");
  CHECK(animation.at("vertices") == comesh.at("vertices_out"));
  CHECK(animation.at("frames").get<int>() > 0);
  CHECK(animation.at("max_iterations_per_frame").get<int>() > 0);
  CHECK(animation.at("max_iteration_ms").get<double>() > 0);
  for (const char* parameter : {"epsilon", "tau", "lambda", "alpha", "mu"}) CHECK(animation.at(parameter).is_number());
  CHECK(animation.at("uniform_material").is_boolean());
  CHECK(animation.at("animation_curve").is_boolean());
  CHECK(animation.at("paper").at("name") == "walk star");
  CHECK(animation.at("paper").at("iterations") == 36);
  CHECK(animation.at("faster").is_boolean());
}
