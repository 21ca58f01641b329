// `inbetween bench mesh`: what `inbetween mesh` does (tracing, the initial map, Comesh
// Optimization) on every scene of a folder, one JSON line per scene; with --contended, beside a
// busy core and against one thread.
#include "bench/bench.h"

#include "bench/contended_core.h"
#include "core/error.h"
#include "multimesh/multimesh.h"
#include "pipeline/scene_multimesh.h"
#include "scene/scene.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench mesh [--assets DIR] [--scenes LIST] [--repeats N] [--threads N] [--contended]\n"
    "\n"
    "Builds the multimesh of every scene in DIR (each DIR/NAME/scene.json) as `inbetween mesh` does:\n"
    "tracing, the initial map, Comesh Optimization, the stiffness painted again; never from a cache.\n"
    "One JSON line per scene: vertices, keys, seconds (median of the repeats), threads (the most\n"
    "threads asked for: 0 = all cores); with --contended also one_thread_seconds (the same build on\n"
    "one thread, alternating with it) and vs_one_thread (seconds over one_thread_seconds).\n"
    "\n"
    "  --assets DIR    folder of scenes (default: the bundled scenes)\n"
    "  --scenes LIST   just these scenes of DIR, by folder name, comma-separated (default: all)\n"
    "  --repeats N     builds per scene and thread count; times are medians (default 1, 3 with --contended)\n"
    "  --threads N     the most threads (default 0: all cores)\n"
    "  --contended     a busy process pinned to one core for the whole run (bench/contended_core.h)\n";

double buildSeconds(const Scene& scene, int threads, int& vertices) {
  SceneMultimeshOptions options;
  options.useCache = false;
  options.threads = threads;
  const auto started = std::chrono::steady_clock::now();
  vertices = sceneMultimesh(scene, options).multimesh->vertexCount();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("mesh");
  const bool contended = a.flag("contended");
  const int repeats = a.integer("repeats", contended ? 3 : 1, 1, 100);
  const int threads = a.integer("threads", 0, 0, cli::kMaxThreads);
  const std::vector<std::string> only = a.has("scenes") ? cli::wordList(a.value("scenes", ""), "--scenes") : std::vector<std::string>{};
  const std::vector<std::filesystem::path> scenes = benchScenes(assets, only, "mesh");
  std::optional<ContendedCore> busy;
  if (contended) busy.emplace();
  for (const auto& file : scenes) {
    const std::string name = file.parent_path().filename().string();
    const Scene scene = loadScene(file.string());
    std::vector<double> seconds, single;
    int vertices = 0;
    for (int r = 0; r < repeats; ++r) {
      showStatus(name + ": build " + std::to_string(r + 1) + " of " + std::to_string(repeats));
      seconds.push_back(buildSeconds(scene, threads, vertices));
      if (contended) single.push_back(buildSeconds(scene, 1, vertices));
    }
    showStatus("");
    nlohmann::json line = {{"scene", name},     {"vertices", vertices}, {"keys", scene.keys.size()},
                           {"threads", threads}, {"repeats", repeats},   {"seconds", median(seconds)}};
    if (contended) {
      line["contended"] = true;
      line["one_thread_seconds"] = median(single);
      line["vs_one_thread"] = median(seconds) / median(single);
    }
    output.printLine(line);
  }
}

}  // namespace

Benchmark meshBenchmark() {
  return {"mesh", "building every bundled scene's multimesh as `inbetween mesh` does", kUsage,
          {"assets", "scenes", "repeats", "threads"}, {"contended"}, run};
}

}  // namespace ib
