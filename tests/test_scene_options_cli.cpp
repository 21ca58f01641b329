// The scene's meshing and sampling options through the front ends: `inbetween mesh` on a sprite
// (the default edge length) and on a big drawing at a tiny edge length (the size guard, exit 2
// before any heavy work); `render` and `export` sampling pixel art as the scene says, the
// command line overriding it; and (under Xvfb, "[window]") the player's View panel starting from
// the scene's sampling.
#include "core/png_image.h"
#include "player/player_window.h"
#include "sprites.h"
#include "testkit/command_run.h"
#include "testkit/drawings.h"

#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

using namespace ib;
namespace fs = std::filesystem;

namespace {

using Run = test::CommandRun;

Run inbetween(const std::string& args) { return test::runCommand(std::string(INBETWEEN_CLI) + " " + args); }

// A fresh folder holding a two-key scene (drawings a.png, b.png) with extra top-level `fields`
// (each followed by a comma); returns the scene file's path.
std::string writeScene(const std::string& name, const RgbaImage& a, const RgbaImage& b, const std::string& fields = "") {
  const fs::path dir = fs::temp_directory_path() / ("inbetween-scene-options-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  writePng((dir / "a.png").string(), a);
  writePng((dir / "b.png").string(), b);
  std::ofstream(dir / "scene.json") << "{\"version\": 1, " << fields << "\"tracing\": {\"min_area\": 4}, "
                                    << "\"keys\": [{\"name\": \"a\", \"drawing\": \"a.png\"}, {\"name\": \"b\", \"drawing\": \"b.png\"}]}";
  return (dir / "scene.json").string();
}

std::string slimeScene(const std::string& name, const std::string& fields = "") {
  return writeScene(name, test::slimePixelArt(false), test::slimePixelArt(true), fields);
}

// Frame 0 of `scene` rendered 8x magnified (128 x 128) on lavapipe.
RgbaImage renderFrame0(const std::string& scene, const std::string& options = "") {
  const std::string out = (fs::path(scene).parent_path() / "frames").string();
  const Run run = inbetween("render " + scene + " -o " + out + " --frames 0 --size 128x128 --no-comesh --device cpu " + options);
  INFO(run.output);
  REQUIRE(run.code == 0);
  return readPng(out + "/frame_0000.png");
}

// Share of the fully opaque pixels (inside the mesh, off its multisampled rim) whose colour is
// exactly one of the slime's palette: 1 for nearest sampling at frame 0 (the key itself); linear
// blends neighbouring texels wherever two colours meet.
double paletteShare(const RgbaImage& image) {
  std::set<uint32_t> palette;
  for (uint32_t c : test::slimePalette()) palette.insert(c);
  int opaque = 0, exact = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      if (p[3] != 255) continue;
      ++opaque;
      exact += palette.count(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]) > 0;
    }
  REQUIRE(opaque > 4000);  // most of the 128 x 128 picture is the slime
  return double(exact) / opaque;
}

// The glTF sampler filters of an export of `scene` (a .gltf, whose JSON is readable).
std::pair<int, int> exportedFilters(const std::string& scene, const std::string& options = "") {
  const std::string out = (fs::path(scene).parent_path() / "out.gltf").string();
  const Run run = inbetween("export " + scene + " -o " + out + " --frames 0:1 --no-comesh " + options);
  INFO(run.output);
  REQUIRE(run.code == 0);
  std::ifstream in(out);
  const nlohmann::json gltf = nlohmann::json::parse(in);
  REQUIRE(gltf.at("samplers").size() >= 1);
  return {gltf["samplers"][0].at("magFilter").get<int>(), gltf["samplers"][0].at("minFilter").get<int>()};
}

constexpr int kNearest = 9728, kLinear = 9729, kNearestMipmapNearest = 9984, kLinearMipmapLinear = 9987;  // glTF / GL enums

}  // namespace

TEST_CASE("cli: mesh gives a 64 px sprite the edge length that follows its size") {
  const std::string scene = writeScene("sprite64", test::birdSprite(64), test::birdSprite(64, 6));
  const Run run = inbetween("mesh " + scene + " --json --no-comesh --no-pictures");
  INFO(run.output);
  REQUIRE(run.code == 0);
  const nlohmann::json report = nlohmann::json::parse(run.output.substr(run.output.find('{')));
  CHECK(report.at("edge_length").get<double>() == Approx(1.9).margin(0.2));
}

TEST_CASE("cli: mesh refuses a mesh past max_vertices with exit code 2, before any heavy work, and says what to do") {
  const RgbaImage big = test::drawShape(1024, 1024, test::disc(512, 512, 440), 40, 90, 200);
  const std::string scene = writeScene("guard", big, big, "\"edge_length\": 0.5, ");
  const auto started = std::chrono::steady_clock::now();
  const Run run = inbetween("mesh " + scene + " --no-pictures");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  INFO(run.output);
  CHECK(run.code == 2);
  CHECK(run.output.find("inbetween: scene.json: edge_length 0.5 px would give a multimesh of about ") != std::string::npos);
  CHECK(run.output.find("more than max_vertices 200,000: set \"edge_length\" to ") != std::string::npos);
  CHECK(run.output.find("raise \"max_vertices\"") != std::string::npos);
  CHECK(seconds < 30);  // tracing 1024 px takes about a second; the build would take many minutes
  CHECK_FALSE(fs::exists(fs::path(scene).parent_path() / "scene.ibmesh"));
}

TEST_CASE("cli: render samples pixel art nearest by default (auto) and as the scene says, and --sampling overrides it") {
  const double automatic = paletteShare(renderFrame0(slimeScene("render-auto")));
  const double linear = paletteShare(renderFrame0(slimeScene("render-linear", "\"sampling\": \"linear\", ")));
  const double overridden =
      paletteShare(renderFrame0(slimeScene("render-override", "\"sampling\": \"linear\", "), "--sampling nearest"));
  const double forcedLinear = paletteShare(renderFrame0(slimeScene("render-auto-linear"), "--sampling linear"));
  INFO("palette share: auto " << automatic << ", scene linear " << linear << ", overridden " << overridden << ", --sampling linear "
                              << forcedLinear);
  CHECK(automatic > 0.995);  // hard pixel edges: every opaque pixel one texel
  CHECK(overridden > 0.995);
  CHECK(linear < 0.9);       // blended where colours meet
  CHECK(forcedLinear < 0.9);
}

TEST_CASE("cli: export writes the scene's sampling as the glTF sampler's filters, and --sampling overrides them") {
  CHECK(exportedFilters(slimeScene("export-auto")) == std::make_pair(kNearest, kNearestMipmapNearest));
  CHECK(exportedFilters(slimeScene("export-nearest", "\"sampling\": \"nearest\", ")) ==
        std::make_pair(kNearest, kNearestMipmapNearest));
  const std::string linear = slimeScene("export-linear", "\"sampling\": \"linear\", ");
  CHECK(exportedFilters(linear) == std::make_pair(kLinear, kLinearMipmapLinear));
  CHECK(exportedFilters(linear, "--sampling nearest") == std::make_pair(kNearest, kNearestMipmapNearest));
  const std::string drawn = writeScene("export-drawn", test::birdSprite(64), test::birdSprite(64, 6));  // antialiased
  CHECK(exportedFilters(drawn) == std::make_pair(kLinear, kLinearMipmapLinear));
}

TEST_CASE("play: the View panel starts from the scene's sampling, --sampling overrides it", "[.window]") {
  const auto opened = [](const std::string& scene, std::optional<render::Sampling> option) {
    play::PlayerSession session(std::make_unique<play::SceneReloader>(scene), {});
    play::PlayerWindowOptions options;
    options.width = 320;
    options.height = 240;
    options.device = vk::DevicePreference::kSoftware;
    options.sampling = option;
    play::PlayerWindow window(session, options);
    return window.ui().view.sampling;
  };
  CHECK(opened(slimeScene("play-auto"), std::nullopt) == render::Sampling::kNearest);
  CHECK(opened(slimeScene("play-linear", "\"sampling\": \"linear\", "), std::nullopt) == render::Sampling::kLinear);
  CHECK(opened(slimeScene("play-override", "\"sampling\": \"linear\", "), render::Sampling::kNearest) == render::Sampling::kNearest);
  const std::string drawn = writeScene("play-drawn", test::birdSprite(64), test::birdSprite(64, 6));
  CHECK(opened(drawn, std::nullopt) == render::Sampling::kLinear);
}
