// `inbetween bench play`: the player's window on every bundled scene: presented frames per second
// while playing, the 95th percentile frame time, and the latency from a parameter change to the
// first frame drawn with it. Needs a display (Xvfb will do); one JSON line per scene.
#include "bench/bench.h"

#include "commands/render_options.h"
#include "core/error.h"
#include "gpu/glfw_window.h"
#include "gpu/vulkan_check.h"
#include "multimesh/multimesh.h"
#include "player/player_window.h"
#include "progress.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench play [--assets DIR] [--scenes LIST] [--size WxH] [--frames N] [--changes N]\n"
    "                            [--edge-length PX] [--samples N] [--device D] [--vsync]\n"
    "\n"
    "Opens the player's window (UI included) on every scene DIR/NAME/scene.json and plays its timeline\n"
    "for N presented frames after a warm-up, then changes tau back and forth N' times while paused and\n"
    "times each change until the first presented frame solved with it. Needs a display: run under\n"
    "`xvfb-run -a -s \"-screen 0 1920x1080x24\"` without one. One JSON line per scene: scene, vertices,\n"
    "triangles, keys, width, height, samples, device, vsync, frames, fps, p50_ms, p95_ms, changes,\n"
    "latency_ms (median), latency_max_ms.\n"
    "\n"
    "  --assets DIR   folder of scenes (default: the bundled scenes)\n"
    "  --scenes LIST  comma-separated scene folder names (default: every one)\n"
    "  --size WxH     window size (default 1280x720)\n"
    "  --frames N     frames timed while playing, after 30 untimed (default 240)\n"
    "  --changes N    parameter changes timed (default 8)\n"
    "  --edge-length PX  mesh every scene at this boundary edge length instead of its own (a copy of\n"
    "                 the scene in a temporary folder; e.g. 1.2 for about 10k vertices on square-arch-notch)\n"
    "  --samples N    MSAA samples (default 2, as the player)\n"
    "  --device D     any, gpu or cpu (default cpu: lavapipe, comparable across machines)\n"
    "  --vsync        present with vsync (default off: the frame rate the player can reach)\n";

using Clock = std::chrono::steady_clock;

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<size_t>(p * static_cast<double>(values.size())))];
}

// Seconds from a change of tau to the first presented frame solved with it: paused, the worker idle
// before the change, so the first frame it shows after is the new one.
double changeLatency(play::PlayerSession& session, play::PlayerWindow& window, double tau) {
  session.worker().waitIdle(600);
  window.frame();
  const std::shared_ptr<const AnimationFrame> before = session.shown();
  const Clock::time_point start = Clock::now();
  session.parameters().set("tau", tau);
  for (;;) {
    window.frame();
    const std::shared_ptr<const AnimationFrame> now = session.shown();
    if (now && now != before) return std::chrono::duration<double>(Clock::now() - start).count();
    if (Clock::now() - start > std::chrono::seconds(600)) throw std::runtime_error("bench play: a change was not solved in 600 s");
  }
}

nlohmann::json benchScene(const std::filesystem::path& file, const play::PlayerWindowOptions& options, int frames, int changes) {
  cli::Progress progress;
  auto reloader = std::make_unique<play::SceneReloader>(file.string(), [&](const std::string& stage, double f) {
    progress.update(file.parent_path().filename().string() + ": " + stage, f);
  });
  progress.finish();
  play::PlayerSession session(std::move(reloader), {});
  play::PlayerWindow window(session, options);
  session.transport().play();
  for (int f = 0; f < 30; ++f) window.frame();
  std::vector<double> ms;
  const Clock::time_point start = Clock::now();
  Clock::time_point last = start;
  for (int f = 0; f < frames; ++f) {
    window.frame();
    const Clock::time_point now = Clock::now();
    ms.push_back(1000 * std::chrono::duration<double>(now - last).count());
    last = now;
  }
  const double seconds = std::chrono::duration<double>(last - start).count();
  session.transport().pause();
  const double tau = session.parameters().get("tau");
  std::vector<double> latencies;
  for (int c = 0; c < changes; ++c) latencies.push_back(1000 * changeLatency(session, window, c % 2 == 0 ? tau * 1.5 : tau));
  const Multimesh& mesh = *session.scene().mesh;
  return {{"scene", file.parent_path().filename().string()},
          {"vertices", mesh.vertexCount()},
          {"triangles", mesh.triangleCount()},
          {"keys", mesh.keyCount()},
          {"width", options.width},
          {"height", options.height},
          {"samples", options.samples},
          {"device", window.context().deviceName()},
          {"vsync", options.vsync},
          {"frames", frames},
          {"fps", frames / seconds},
          {"p50_ms", percentile(ms, 0.5)},
          {"p95_ms", percentile(ms, 0.95)},
          {"changes", changes},
          {"latency_ms", changes ? percentile(latencies, 0.5) : 0.0},
          {"latency_max_ms", changes ? *std::max_element(latencies.begin(), latencies.end()) : 0.0}};
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("play");
  const std::vector<std::string> only = a.has("scenes") ? cli::wordList(a.value("scenes", ""), "--scenes") : std::vector<std::string>{};
  const std::vector<std::filesystem::path> files = benchScenes(assets, only, "play");
  play::PlayerWindowOptions options;
  const std::array<int, 2> size = parseSize(a.value("size", "1280x720"), "--size");
  options.width = size[0];
  options.height = size[1];
  options.vsync = a.flag("vsync");
  options.samples = a.integer("samples", options.samples, 1, 64);
  const std::string device = a.value("device", "cpu");
  if (device == "gpu") options.device = vk::DevicePreference::kHardware;
  else if (device == "cpu") options.device = vk::DevicePreference::kSoftware;
  else if (device != "any") throw InputError("--device: '" + device + "' is not any, gpu or cpu");
  const int frames = a.integer("frames", 240, 1, 100000);
  const int changes = a.integer("changes", 8, 0, 1000);
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY"))
    throw InputError("bench play: no display (DISPLAY is not set); run it under xvfb-run -a");
  const double edgeLength = edgeLengthOption(a);
  for (const auto& file : files) {
    try {
      nlohmann::json line = benchScene(edgeLength > 0 ? sceneWithEdgeLength(file, edgeLength, "play") : file, options, frames, changes);
      line["scene"] = file.parent_path().filename().string();
      if (edgeLength > 0) line["edge_length"] = edgeLength;
      output.printLine(line);
    } catch (const vk::WindowError& e) {
      throw InputError(std::string("bench play: ") + e.what());
    } catch (const vk::VulkanError& e) {
      throw InputError(std::string("bench play: no usable Vulkan device: ") + e.what());
    }
  }
}

}  // namespace

Benchmark playBenchmark() {
  return {"play", "the player's window: fps, frame times, parameter latency", kUsage,
          {"assets", "scenes", "size", "frames", "changes", "edge-length", "samples", "device"}, {"vsync"}, run};
}

}  // namespace ib
