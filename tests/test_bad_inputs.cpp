// The bad-input suite: every command (mesh, render, export, play scripted) on a folder of broken
// inputs. Each run must exit 2 with one line naming the problem, leave no file behind, leave an
// earlier output where it was untouched, and end within kSeconds (a hang is killed and fails).
// Runs under Xvfb (the player's window), one X server at a time.
#include "core/atomic_file.h"
#include "core/png_image.h"
#include "testkit/command_run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/stat.h>
#include <zlib.h>

namespace fs = std::filesystem;

namespace {

constexpr int kSeconds = 30;  // per command; the slowest seen is well under 5 s

const fs::path kRoot = fs::path(INBETWEEN_BUILD) / "bad-inputs";
const std::string kGoodScene = std::string(INBETWEEN_ASSETS) + "/square-arch-notch/scene.json";

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A PNG chunk with its CRC.
std::string chunk(const std::string& type, const std::string& data) {
  std::string out;
  const auto be32 = [&](uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out += static_cast<char>((v >> s) & 0xff);
  };
  be32(static_cast<uint32_t>(data.size()));
  out += type + data;
  const std::string crcOf = type + data;
  be32(static_cast<uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(crcOf.data()), static_cast<uInt>(crcOf.size()))));
  return out;
}

std::string pngDeclaring(uint32_t width, uint32_t height) {
  std::string ihdr;
  for (uint32_t v : {width, height})
    for (int s = 24; s >= 0; s -= 8) ihdr += static_cast<char>((v >> s) & 0xff);
  ihdr += std::string("\x08\x06\x00\x00\x00", 5);
  // An IDAT after the header, so that a reader gets as far as the declared size.
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8)) +
         chunk("IEND", "");
}

// The good scene, its drawings named by absolute paths so that the copy works from any folder.
nlohmann::json goodScene() {
  nlohmann::json scene = nlohmann::json::parse(slurp(kGoodScene));
  const std::string dir = fs::path(kGoodScene).parent_path().string();
  for (auto& key : scene["keys"]) key["drawing"] = dir + "/" + key["drawing"].get<std::string>();
  return scene;
}

// The good scene with key 0's drawing replaced by `drawing` (relative to the bad folder).
std::string sceneWithDrawing(const std::string& drawing) {
  nlohmann::json scene = goodScene();
  scene["keys"][0]["drawing"] = drawing;
  return scene.dump(2);
}

// The good scene with a JSON field (a path of keys, e.g. {"solver", "tau"}) set to raw JSON text,
// which may be what JSON cannot hold (NaN, 1e999): written in through a placeholder.
std::string sceneWith(const std::vector<std::string>& path, const std::string& raw) {
  nlohmann::json scene = goodScene();
  nlohmann::json* field = &scene;
  for (const std::string& name : path) field = &(*field)[name];
  *field = "@RAW@";
  return std::regex_replace(scene.dump(2), std::regex("\"@RAW@\""), raw);
}

// The good scene with a second cut in the square, a slit across its notch.
std::string crossingCuts() {
  nlohmann::json scene = goodScene();
  scene["keys"][0]["cuts"].push_back({{"name", "x"}, {"kind", "slit"}, {"points", {{44, 80}, {84, 80}}}});
  scene["keys"][1]["features"]["x.start"] = {30, 70};
  scene["keys"][1]["features"]["x.end"] = {98, 70};
  return scene.dump(2);
}

// The good scene with the notch's two sides swapped in the arch: its features then run around
// the outline in another order than in the square.
std::string featuresSwapped() {
  nlohmann::json scene = goodScene();
  nlohmann::json& features = scene["keys"][1]["features"];
  std::swap(features["split.left"], features["split.right"]);
  return scene.dump(2);
}

struct BadInput {
  std::string name;     // the test's words
  std::string scene;    // scene file to run on
  std::string message;  // regex the one line must match
  std::string extra = "";  // more arguments for every command (e.g. --mesh FILE)
};

// Writes the folder of broken inputs once per run.
const std::vector<BadInput>& badInputs() {
  static const std::vector<BadInput> inputs = [] {
    fs::remove_all(kRoot);
    fs::create_directories(kRoot);
    const auto file = [](const std::string& name, const std::string& bytes) {
      std::ofstream(kRoot / name, std::ios::binary) << bytes;
      return (kRoot / name).string();
    };
    const std::string good = slurp(fs::path(kGoodScene).parent_path() / "square.png");
    std::string corrupt = good;
    for (size_t i = good.size() / 2; i < good.size() / 2 + 16; ++i) corrupt[i] = static_cast<char>(~corrupt[i]);
    file("truncated.png", good.substr(0, good.size() / 2));
    file("corrupt.png", corrupt);
    file("huge.png", pngDeclaring(100000, 100000));
    file("zero-bytes.png", "");
    file("text.png", "this is not a PNG\n");
    ib::RgbaImage clear;
    clear.width = clear.height = 64;
    clear.hasAlpha = true;
    clear.pixels.assign(64 * 64 * 4, 0);
    ib::writePng((kRoot / "transparent.png").string(), clear);
    fs::create_directories(kRoot / "folder.png");
    mkfifo((kRoot / "fifo.png").c_str(), 0644);
    fs::create_symlink("loop.png", kRoot / "loop.png");
    const auto scene = [&](const std::string& name, const std::string& text) { return file(name + ".json", text); };
    // A scene whose drawing is the scene itself, through a symlink.
    const std::string self = scene("self", sceneWithDrawing("self-link.png"));
    fs::create_symlink("self.json", kRoot / "self-link.png");
    // Multimesh files for --mesh: cut in half, and one checksum byte changed.
    const std::string built = (kRoot / "good.ibmesh").string();
    const test::CommandRun mesh = test::runCommand(std::string(INBETWEEN_CLI) + " mesh " + kGoodScene + " -o " + built + " --no-pictures");
    if (mesh.code != 0) throw std::runtime_error("could not build " + built + ": " + mesh.output);
    const std::string bytes = slurp(built);
    file("half.ibmesh", bytes.substr(0, bytes.size() / 2));
    std::string wrongSum = bytes;
    wrongSum.back() = static_cast<char>(~wrongSum.back());
    file("wrong-checksum.ibmesh", wrongSum);
    fs::remove(built);
    fs::remove(kRoot / "good.initial.ibmesh");
    return std::vector<BadInput>{
        {"a truncated PNG", scene("truncated", sceneWithDrawing("truncated.png")), "truncated.png.*(PNG|png)"},
        {"a corrupt PNG", scene("corrupt", sceneWithDrawing("corrupt.png")), "corrupt.png.*(PNG|png)"},
        {"a PNG declaring 100000 x 100000 pixels", scene("huge", sceneWithDrawing("huge.png")), "huge.png.*out of range"},
        {"an empty (zero-byte) PNG", scene("zero-bytes", sceneWithDrawing("zero-bytes.png")), "zero-bytes.png"},
        {"a text file named .png", scene("text", sceneWithDrawing("text.png")), "text.png.*not a readable PNG"},
        {"a fully transparent drawing", scene("transparent", sceneWithDrawing("transparent.png")), "transparent.png.*empty"},
        {"a folder named .png", scene("folder", sceneWithDrawing("folder.png")), "folder.png.*not a (regular )?file"},
        {"a named pipe as the drawing", scene("fifo", sceneWithDrawing("fifo.png")), "fifo.png.*not a regular file"},
        {"a symlink loop as the drawing", scene("loop", sceneWithDrawing("loop.png")), "loop.png"},
        {"a scene whose drawing is the scene itself through a symlink", self, "self-link.png.*not a readable PNG"},
        {"malformed JSON", scene("malformed", "{\"version\": 1, \"keys\": ["), "malformed JSON"},
        {"JSON with NaN", scene("nan", sceneWith({"edge_length"}, "NaN")), "malformed JSON"},
        {"edge_length of the wrong type", scene("wrong-type", sceneWith({"edge_length"}, "\"six\"")), "edge_length"},
        {"keys of the wrong type", scene("keys-type", "{\"version\": 1, \"keys\": {\"a\": 1}}"), "keys"},
        {"an infinite edge_length", scene("infinite", sceneWith({"edge_length"}, "1e999")), "malformed JSON: a number too large"},
        {"an edge_length too fine to mesh", scene("too-fine", sceneWith({"edge_length"}, "1e-6")), "edge_length"},
        {"a huge lambda", scene("huge-lambda", sceneWith({"solver", "lambda"}, "1e999")), "malformed JSON: a number too large"},
        {"a negative tau", scene("negative-tau", sceneWith({"solver", "tau"}, "-1")), "solver: tau"},
        {"an infinite gravity", scene("infinite-gravity", sceneWith({"dynamics", "gravity"}, "[0, 1e999]")), "malformed JSON: a number too large"},
        {"cuts that cross each other", scene("crossing-cuts", crossingCuts()), "cut .x.: leaves the shape.*crosses the outline"},
        {"features in different orders",
         scene("feature-order", featuresSwapped()),
         "outlines do not match"},
        {"a multimesh file cut in half", kGoodScene, "half.ibmesh", "--mesh " + (kRoot / "half.ibmesh").string()},
        {"a multimesh file with a wrong checksum", kGoodScene, "wrong-checksum.ibmesh.*checksum",
         "--mesh " + (kRoot / "wrong-checksum.ibmesh").string()},
        {"a scene that is a folder", (kRoot / "folder.png").string(), "folder.png"},
        {"a scene that is a named pipe", (kRoot / "fifo.png").string(), "fifo.png.*not a regular file"},
    };
  }();
  return inputs;
}

struct Command {
  std::string name;
  std::string arguments;  // after the scene; OUT stands for the output path
  std::string output;     // the output path's name in the run's folder
  bool takesMesh;         // accepts --mesh
};

const std::vector<Command> kCommands = {
    {"mesh", "-o OUT --no-pictures", "out.ibmesh", false},
    {"render", "-o OUT --frames 0:1 --size 64x64 --device cpu", "frames", true},
    {"export", "-o OUT", "out.glb", true},
    {"play", "--frames 2 --screenshot OUT --size 64x64 --device cpu", "shot.png", false},
};

void checkEveryCommand(const BadInput& input) {
  for (const Command& command : kCommands) {
    if (!input.extra.empty() && !command.takesMesh) continue;
    INFO(command.name << " on " << input.scene << " " << input.extra);
    const fs::path runDir = kRoot / ("run-" + command.name);
    fs::remove_all(runDir);
    fs::create_directories(runDir);
    // An earlier good output where this one would go: it must survive the failed run untouched.
    const fs::path out = runDir / command.output;
    const std::string earlier = "an earlier output";
    if (command.output != "frames") ib::writeFileAtomically(out.string(), earlier);
    std::string arguments = std::regex_replace(command.arguments, std::regex("OUT"), out.string());
    const auto started = std::chrono::steady_clock::now();
    const test::CommandRun run = test::runCommand("timeout -s KILL " + std::to_string(kSeconds) + " " + INBETWEEN_CLI + " " +
                                                  command.name + " " + input.scene + " " + arguments + " " + input.extra);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    INFO("output: " << run.output);
    CHECK(run.code == 2);
    CHECK(seconds < kSeconds);
    std::istringstream lines(run.output);
    std::string line, message;
    int count = 0;
    while (std::getline(lines, line))
      if (!line.empty()) {
        ++count;
        message = line;
      }
    CHECK(count == 1);
    CHECK(std::regex_search(message, std::regex("^inbetween: ")));
    CHECK(std::regex_search(message, std::regex(input.message)));
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(runDir)) left.push_back(entry.path().filename().string());
    if (command.output == "frames") {
      CHECK(left.empty());
    } else {
      CHECK(left == std::vector<std::string>{command.output});
      CHECK(slurp(out) == earlier);
    }
  }
}

}  // namespace

TEST_CASE("bad input: every broken input makes every command exit 2 with one line naming it, leaving no file and every earlier output intact, within 30 s", "[.window]") {
  for (const BadInput& input : badInputs()) {
    SECTION(input.name) { checkEveryCommand(input); }
  }
}

TEST_CASE("bad input: an output folder that cannot be written exits 2 naming it, for every command", "[.window]") {
  // /proc refuses new files even to root, which chmod cannot do.
  for (const Command& command : kCommands) {
    INFO(command.name);
    const std::string out = "/proc/inbetween-cannot-write/" + command.output;
    const test::CommandRun run = test::runCommand("timeout -s KILL " + std::to_string(kSeconds) + " " + INBETWEEN_CLI + " " + command.name +
                                                  " " + kGoodScene + " " +
                                                  std::regex_replace(command.arguments, std::regex("OUT"), out) +
                                                  (command.name == "play" ? "" : " --no-comesh"));
    INFO("output: " << run.output);
    CHECK(run.code == 2);
    CHECK(std::regex_search(run.output, std::regex("/proc/inbetween-cannot-write")));
  }
}
