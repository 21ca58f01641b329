// `inbetween bench anim`: the frame stream (timeline, warm starts, dynamics) over bundled scenes,
// one JSON line per scene.
#include "bench/bench.h"

#include "animation/frame_stream.h"
#include "core/error.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "pipeline/scene_frames.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "scene/scene.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench anim [--assets DIR] [--comesh] [--threads N]\n"
    "\n"
    "Plays every scene in DIR (each DIR/NAME/scene.json) through its timeline with the frame stream\n"
    "every front end uses: warm starts, and dynamics where the scene asks for them. One JSON line per\n"
    "scene: vertices, keys, frames, dynamics (on/off), ms_per_frame (mean), max_ms_per_frame,\n"
    "iterations_per_frame (mean), converged (share of frames), max_deviation (shape sizes from plain\n"
    "interpolation).\n"
    "\n"
    "  --assets DIR   folder of scenes (default: the bundled scenes)\n"
    "  --comesh       run Comesh Optimization before playing (default: the initial map)\n"
    "  --threads N    solver threads, 0 = all cores (default 0)\n";

nlohmann::json playScene(const std::filesystem::path& file, bool comesh, int threads, cli::Progress& progress) {
  const std::string name = file.parent_path().filename().string();
  progress.update(name + ": building the multimesh", 0);
  const Scene scene = loadScene(file.string());
  SceneMultimeshOptions meshOptions;
  meshOptions.useCache = false;  // from the drawings: a .ibmesh left in DIR must not change the figures
  meshOptions.comesh = comesh;
  const auto built = sceneMultimesh(scene, meshOptions, [&](const std::string& stage, double) {
    progress.update(name + ": " + stage, 0);  // the bar shows the frames played
  });
  const Multimesh& mesh = *built.multimesh;
  FrameOptions options;
  options.solver.threads = threads;
  FrameStream stream = sceneFrameStream(scene, mesh, options);
  double total = 0, slowest = 0, deviation = 0;
  long iterations = 0;
  int converged = 0;
  while (!stream.done()) {
    const AnimationFrame frame = stream.next();
    total += frame.milliseconds;
    slowest = std::max(slowest, frame.milliseconds);
    deviation = std::max(deviation, frame.deviation);
    iterations += frame.iterations;
    converged += frame.converged;
    progress.update(name + ": frame " + std::to_string(frame.index + 1) + " of " + std::to_string(stream.frameCount()),
                    (frame.index + 1.0) / stream.frameCount());
  }
  const int frames = stream.frameCount();
  return {{"scene", name},
          {"vertices", mesh.vertexCount()},
          {"keys", mesh.keyCount()},
          {"frames", frames},
          {"dynamics", scene.dynamics.enabled()},
          {"ms_per_frame", total / frames},
          {"max_ms_per_frame", slowest},
          {"iterations_per_frame", static_cast<double>(iterations) / frames},
          {"converged", static_cast<double>(converged) / frames},
          {"max_deviation", deviation}};
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("anim");
  const int threads = cli::integerList(a.value("threads", "0"), "threads", 0, 256).front();
  if (!std::filesystem::is_directory(assets)) throw InputError("bench anim: --assets: " + assets.string() + " is not a folder");
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(assets))
    if (std::filesystem::exists(entry.path() / "scene.json")) scenes.push_back(entry.path() / "scene.json");
  std::sort(scenes.begin(), scenes.end());
  if (scenes.empty()) throw InputError("bench anim: --assets: no NAME/scene.json in " + assets.string());
  for (const auto& file : scenes) {
    cli::Progress progress;
    const nlohmann::json line = playScene(file, a.flag("comesh"), threads, progress);
    progress.finish();
    output.printLine(line);
  }
}

}  // namespace

Benchmark animBenchmark() {
  return {"anim", "playing every bundled scene's timeline", kUsage, {"assets", "threads"}, {"comesh"}, run};
}

}  // namespace ib
