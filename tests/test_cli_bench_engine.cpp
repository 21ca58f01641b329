// The benchmarks that need the engine: `inbetween bench render` headless on lavapipe, and (under
// Xvfb, "[.window]", run by ctest through xvfb-run) `inbetween bench play` in the player's window.
// Every stdout line is one JSON object of the case, with the fields its --help documents
// (apps/bench/bench_render.cpp, bench_play.cpp) and positive times.
#include "cli_support.h"

#include <catch2/catch.hpp>

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
