// The benchmarks that need the engine: `inbetween bench render` headless on lavapipe, and (under
// Xvfb, "[.window]", run by ctest through xvfb-run) `inbetween bench play` in the player's window;
// `inbetween bench ghost` on scenes written here; `inbetween bench keys` on bundled scenes.
// Every stdout line is one JSON object of the case, with the fields its --help documents
// (apps/bench/bench_render.cpp, bench_play.cpp) and positive times.
#include "cli_support.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

using Catch::StartsWith;
using test::CommandRun;
using test::inbetween;
using test::jsonLines;
using Json = nlohmann::json;

TEST_CASE("cli: bench render prints a JSON line per size") {
  const CommandRun run = inbetween({"bench", "render", "--triangles", "1k,2k", "--size", "320x180", "--frames", "3"});
  INFO(run.output);
  REQUIRE(run.code == 0);
  const std::vector<Json> lines = jsonLines(run.out);
  REQUIRE(lines.size() == 2);  // one per --triangles entry, in order
  for (size_t i = 0; i < lines.size(); ++i) {
    const Json& line = lines[i];
    INFO(line.dump());
    CHECK(line.at("bench") == "render");
    CHECK(line.at("arch") == INBETWEEN_ARCH);
    const int triangles = (i == 0 ? 1000 : 2000);  // about: the strip has whole rows
    CHECK(line.at("triangles").get<int>() >= triangles * 0.9);
    CHECK(line.at("triangles").get<int>() <= triangles * 1.2);
    CHECK(line.at("vertices").get<int>() > 0);
    CHECK(line.at("width") == 320);
    CHECK(line.at("height") == 180);
    CHECK(line.at("samples") == 4);  // the default
    CHECK(line.at("frames") == 3);
    CHECK_THAT(line.at("device").get<std::string>(), StartsWith("llvmpipe"));  // --device cpu, the default
    CHECK(line.at("fps").get<double>() > 0);
    CHECK(line.at("ms_per_frame").get<double>() > 0);
  }
}

TEST_CASE("cli: bench render with a malformed --size exits 2") {
  const CommandRun run = inbetween({"bench", "render", "--size", "320by180"});
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, StartsWith("inbetween: --size: '320by180' is not WIDTHxHEIGHT"));
}

TEST_CASE("window: bench play prints a JSON line for the scene it plays under Xvfb", "[.window]") {
  const CommandRun run = inbetween(
      {"bench", "play", "--scenes", "square-arch-notch", "--size", "640x360", "--frames", "10", "--changes", "2"});
  INFO(run.output);
  REQUIRE(run.code == 0);
  const std::vector<Json> lines = jsonLines(run.out);
  REQUIRE(lines.size() == 1);  // --scenes names one
  const Json& line = lines[0];
  INFO(line.dump());
  CHECK(line.at("bench") == "play");
  CHECK(line.at("arch") == INBETWEEN_ARCH);
  CHECK(line.at("scene") == "square-arch-notch");
  CHECK(line.at("keys") == 2);
  CHECK(line.at("vertices").get<int>() > 0);
  CHECK(line.at("triangles").get<int>() > 0);
  CHECK(line.at("width") == 640);
  CHECK(line.at("height") == 360);
  CHECK(line.at("frames") == 10);
  CHECK(line.at("changes") == 2);
  CHECK(line.at("vsync") == false);
  CHECK(line.at("samples").get<int>() >= 1);
  CHECK(line.at("fps").get<double>() > 0);
  CHECK(line.at("p50_ms").get<double>() > 0);
  CHECK(line.at("p95_ms").get<double>() >= line.at("p50_ms").get<double>());
  CHECK(line.at("latency_ms").get<double>() > 0);
  CHECK(line.at("latency_max_ms").get<double>() >= line.at("latency_ms").get<double>());
}

TEST_CASE("cli: bench ghost finds no ghost where the keys are one drawing, and one where a key's artwork moves") {
  // Two keys, each the cat of tests/correspondence drawn with its tail down: every inbetween is
  // that drawing, up to the renderer's resampling; then the second key's tail up, so the body
  // agrees and the tail does not.
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "inbetween-cli-bench-ghost";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder / "same");
  std::filesystem::create_directories(folder / "tail");
  const std::filesystem::path cat = std::filesystem::path(INBETWEEN_SOURCE_DIR) / "tests" / "correspondence" / "cat-tail";
  const auto scene = [&](const std::string& name, const std::string& second) {
    std::filesystem::copy_file(cat / "down.png", folder / name / "a.png");
    std::filesystem::copy_file(cat / second, folder / name / "b.png");
    std::ofstream((folder / name / "scene.json").string()) << (R"({"version": 1, "keys": [{"name": "a", "drawing": "a.png"}, {"name": "b", "drawing": "b.png"}],
                        "timeline": {"fps": 8, "marks": [{"time": 0, "key": "a"}, {"time": 1, "key": "b"}]}})");
  };
  scene("same", "down.png");
  scene("tail", "up.png");
  const CommandRun run = inbetween({"bench", "ghost", "--assets", folder.string()});
  INFO(run.output);
  REQUIRE(run.code == 0);
  const std::vector<Json> lines = jsonLines(run.out);
  REQUIRE(lines.size() == 2);  // by folder name: same, tail
  const Json& same = lines[0];
  CHECK(same.at("scene") == "same");
  CHECK(same.at("frames") == 7);  // 9 frames, the two keys' left out
  CHECK(same.at("drawn_pixels").get<int>() > 50000);
  CHECK(same.at("drawn_mean").get<double>() < 1.5);  // 0.63 measured: the renderer resampling the drawing
  CHECK(same.at("drawn_share").get<double>() < 0.02);  // 0.9%: antialiased edges
  const Json& tail = lines[1];
  CHECK(tail.at("drawn_pixels").get<int>() > 40000);
  CHECK(tail.at("drawn_pixels").get<int>() < same.at("drawn_pixels").get<int>());
  CHECK(tail.at("drawn_mean").get<double>() > 5 * same.at("drawn_mean").get<double>());  // 17.6 measured
  std::filesystem::remove_all(folder);
}

TEST_CASE("cli: bench keys finds every bundled key it renders to be its drawing, at its size and twice it, and writes the frames it was asked for") {
  const std::filesystem::path frames = std::filesystem::temp_directory_path() / "inbetween-cli-bench-keys";
  std::filesystem::remove_all(frames);
  const CommandRun run = inbetween({"bench", "keys", "--scenes", "slime-sprite,square-arch-notch", "--frames", frames.string()});
  INFO(run.output);
  REQUIRE(run.code == 0);
  const std::vector<Json> lines = jsonLines(run.out);
  REQUIRE(lines.size() == 4);  // two scenes, scales 1 and 2
  for (const Json& line : lines) {
    CHECK(line.at("bench") == "keys");
    CHECK(line.at("over_2") == 0);
    CHECK(line.at("worst").get<int>() <= 2);
    CHECK(line.at("pixels").get<long long>() >= 2 * 128 * 128);
  }
  CHECK(lines[0].at("scene") == "slime-sprite");
  CHECK(lines[0].at("sampling") == "linear");
  CHECK(lines[0].at("keys") == 3);
  CHECK(lines[1].at("scale") == 2);
  CHECK(lines[2].at("sampling") == "nearest");  // square-arch-notch is pixel art
  CHECK(std::filesystem::exists(frames / "slime-sprite_key_2_x2.png"));
  CHECK(std::filesystem::exists(frames / "square-arch-notch_key_1_x1.png"));
  std::filesystem::remove_all(frames);

  const CommandRun bad = inbetween({"bench", "keys", "--scales", "1,9"});
  CHECK(bad.code == 2);
  CHECK_THAT(bad.err, Catch::Contains("scales"));
}
