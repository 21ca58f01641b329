// `inbetween bench anim`: the frame stream (timeline, warm starts, dynamics) over bundled scenes,
// one JSON line per scene.
#include "bench/bench.h"

#include "animation/frame_stream.h"
#include "bench/contended_core.h"
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
#include <optional>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench anim [--assets DIR] [--scenes LIST] [--comesh] [--threads N] [--repeats N] [--contended]\n"
    "\n"
    "Plays every scene in DIR (each DIR/NAME/scene.json) through its timeline with the frame stream\n"
    "every front end uses (pipeline/scene_frames.h): warm starts, and dynamics where the scene asks\n"
    "for them. One JSON line per scene: vertices, keys, frames, dynamics (on/off), ms_per_frame (mean;\n"
    "the median of the repeats), max_ms_per_frame, iterations_per_frame (mean), converged (share of\n"
    "frames), max_deviation (shape sizes from plain interpolation), threads_used (mean threads the\n"
    "frames' solves ran on); with --contended also one_thread_ms_per_frame (the same play on one\n"
    "thread, alternating with it) and vs_one_thread (ms_per_frame over one_thread_ms_per_frame).\n"
    "\n"
    "  --assets DIR    folder of scenes (default: the bundled scenes)\n"
    "  --scenes LIST   just these scenes of DIR, by folder name, comma-separated (default: all)\n"
    "  --comesh        run Comesh Optimization before playing (default: the initial map)\n"
    "  --threads N     the most solver threads, 0 = all cores (default 0)\n"
    "  --repeats N     plays per scene and thread count; times are medians (default 1, 3 with --contended)\n"
    "  --contended     a busy process pinned to one core for the whole run (bench/contended_core.h)\n";

struct Play {
  double msPerFrame = 0, slowest = 0, deviation = 0, threadsUsed = 0;
  long iterations = 0;
  int converged = 0, frames = 0;
};

Play play(const Scene& scene, const Multimesh& mesh, int threads, const std::string& name, cli::Progress& progress) {
  FrameOptions options;
  options.solver.threads = threads;
  FrameStream stream = sceneFrameStream(scene, mesh, options);
  Play out;
  double total = 0;
  while (!stream.done()) {
    const AnimationFrame frame = stream.next();
    total += frame.milliseconds;
    out.slowest = std::max(out.slowest, frame.milliseconds);
    out.deviation = std::max(out.deviation, frame.deviation);
    out.iterations += frame.iterations;
    out.converged += frame.converged;
    out.threadsUsed += frame.threads;
    progress.update(name + ": frame " + std::to_string(frame.index + 1) + " of " + std::to_string(stream.frameCount()),
                    (frame.index + 1.0) / stream.frameCount());
  }
  out.frames = stream.frameCount();
  out.msPerFrame = total / out.frames;
  out.threadsUsed /= out.frames;
  return out;
}

double medianOf(std::vector<Play> plays, double Play::*field) {
  std::sort(plays.begin(), plays.end(), [&](const Play& a, const Play& b) { return a.*field < b.*field; });
  return plays[plays.size() / 2].*field;
}

nlohmann::json playScene(const std::filesystem::path& file, bool comesh, int threads, int repeats, bool contended,
                         cli::Progress& progress) {
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
  std::vector<Play> plays, single;
  for (int r = 0; r < repeats; ++r) {
    plays.push_back(play(scene, mesh, threads, name, progress));
    if (contended) single.push_back(play(scene, mesh, 1, name + " (one thread)", progress));
  }
  const Play& first = plays.front();
  nlohmann::json line = {{"scene", name},
                         {"vertices", mesh.vertexCount()},
                         {"keys", mesh.keyCount()},
                         {"frames", first.frames},
                         {"dynamics", scene.dynamics.enabled()},
                         {"ms_per_frame", medianOf(plays, &Play::msPerFrame)},
                         {"max_ms_per_frame", medianOf(plays, &Play::slowest)},
                         {"iterations_per_frame", static_cast<double>(first.iterations) / first.frames},
                         {"converged", static_cast<double>(first.converged) / first.frames},
                         {"max_deviation", first.deviation},
                         {"threads_used", medianOf(plays, &Play::threadsUsed)}};
  if (contended) {
    line["contended"] = true;
    line["one_thread_ms_per_frame"] = medianOf(single, &Play::msPerFrame);
    line["vs_one_thread"] = medianOf(plays, &Play::msPerFrame) / medianOf(single, &Play::msPerFrame);
  }
  return line;
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("anim");
  const int threads = cli::integerList(a.value("threads", "0"), "threads", 0, cli::kMaxThreads).front();
  const bool contended = a.flag("contended");
  const int repeats = a.integer("repeats", contended ? 3 : 1, 1, 100);
  const std::vector<std::string> only = a.has("scenes") ? cli::wordList(a.value("scenes", ""), "--scenes") : std::vector<std::string>{};
  const std::vector<std::filesystem::path> scenes = benchScenes(assets, only, "anim");
  std::optional<ContendedCore> busy;
  if (contended) busy.emplace();
  for (const auto& file : scenes) {
    cli::Progress progress;
    const nlohmann::json line = playScene(file, a.flag("comesh"), threads, repeats, contended, progress);
    progress.finish();
    output.printLine(line);
  }
}

}  // namespace

Benchmark animBenchmark() {
  return {"anim", "playing every bundled scene's timeline", kUsage, {"assets", "scenes", "threads", "repeats"},
          {"comesh", "contended"}, run};
}

}  // namespace ib
