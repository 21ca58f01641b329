// `inbetween bench examples`: the paper's animation examples (assets/, docs/gallery.md) measured as
// its Tables 2 and 3 are, one JSON line per example and table, each beside the paper's row.
#include "bench/bench.h"

#include "animation/frame_stream.h"
#include "comesh/comesh.h"
#include "core/error.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "pipeline/scene_frames.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "scene/scene.h"

#include <algorithm>
#include <filesystem>
#include <optional>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench examples [--assets DIR] [--only NAME] [--threads N]\n"
    "\n"
    "The paper's examples in DIR, each built from its drawings, optimized by Comesh and played\n"
    "through its timeline (dynamics included). Two JSON lines per example, with the paper's row\n"
    "(\"paper\", null where the paper has none) and \"faster\" (ours below the paper's time):\n"
    "  table 2  keys, vertices/triangles/cohesive edges in and out, inner and outer iterations,\n"
    "           flip/collapse/split seconds and seconds (Comesh Optimization's total)\n"
    "  table 3  frames, max_iterations_per_frame, max_iteration_ms (the largest of every frame's\n"
    "           wall time over its iterations: one local-global iteration with its share of the\n"
    "           frame's setup and factorizations), and the parameters: epsilon, tau, alpha, mu,\n"
    "           uniform_material (nothing painted), animation_curve (some mark eases)\n"
    "\n"
    "  --assets DIR   folder holding the examples (default: the bundled scenes)\n"
    "  --only NAME    one example, by folder name\n"
    "  --threads N    solver threads, 0 = all cores (default 0)\n";

// The paper's Tables 2 and 3 (Zhu et al. 2017), measured on its authors' machine.
struct PaperRow {
  const char* name;
  int keys, verticesIn, verticesOut, trianglesIn, trianglesOut, cohesiveIn, cohesiveOut, inner, outer;
  double flipSeconds, collapseSeconds, splitSeconds, seconds;
  int iterations;           // Table 3: maximal iterations per frame
  double localSeconds, globalMs;  // Table 3: maximal local step (s) and global step (ms)
};

struct Example {
  const char* folder;
  std::optional<PaperRow> paper;  // none: the example is in the paper's figures but not its tables
};

const std::vector<Example>& examples() {
  static const std::vector<Example> list = {
      {"arch-stretch", std::nullopt},
      {"arch-split", std::nullopt},
      {"star-regular", std::nullopt},
      {"star-hard3", std::nullopt},
      {"star-hard6", std::nullopt},
      {"circles-in-circles", PaperRow{"circle in circle", 2, 201, 201, 241, 241, 126, 126, 70, 3, 0.024, 0.012, 0.013, 0.137, 52, 0.007, 2.106}},
      {"circles-open", std::nullopt},
      {"cell-splitting", PaperRow{"cell splitting", 3, 573, 570, 978, 972, 142, 142, 572, 15, 1.009, 0.547, 0.487, 4.078, 173, 0.202, 6.144}},
      {"chinese-character", PaperRow{"chinese character", 2, 277, 277, 382, 379, 10, 10, 36, 4, 0.023, 0.012, 0.012, 0.119, 38, 0.133, 1.307}},
      {"walk-star", PaperRow{"walk star", 8, 89, 89, 93, 93, 24, 24, 243, 7, 0.085, 0.049, 0.051, 0.284, 36, 0.027, 0.286}},
      {"stylized-walk", PaperRow{"stylized walk", 16, 132, 132, 161, 161, 0, 0, 243, 6, 0.311, 0.166, 0.166, 0.824, 40, 0.038, 0.441}},
      {"growing-flower", PaperRow{"growing flower", 4, 163, 159, 213, 205, 24, 24, 54, 5, 0.023, 0.018, 0.028, 0.104, 53, 0.089, 0.592}},
      {"flying-bird", PaperRow{"flying bird", 3, 226, 226, 265, 265, 0, 0, 60, 7, 0.028, 0.018, 0.016, 0.141, 43, 0.052, 0.502}},
      {"continental-drift", PaperRow{"continental drift", 4, 271, 269, 362, 357, 104, 104, 2565, 29, 8.841, 5.539, 1.067, 18.322, 79, 0.085, 1.817}},
  };
  return list;
}

nlohmann::json comeshTable(const std::string& name, const ComeshReport& r, const std::optional<PaperRow>& p) {
  nlohmann::json line = {{"table", 2},
                         {"scene", name},
                         {"keys", r.keys},
                         {"vertices_in", r.verticesIn},
                         {"vertices_out", r.verticesOut},
                         {"triangles_in", r.trianglesIn},
                         {"triangles_out", r.trianglesOut},
                         {"cohesive_in", r.cohesiveIn},
                         {"cohesive_out", r.cohesiveOut},
                         {"inner", r.innerIterations},
                         {"outer", r.outerIterations},
                         {"flip_seconds", r.remesh.flipSeconds},
                         {"collapse_seconds", r.remesh.collapseSeconds},
                         {"split_seconds", r.remesh.splitSeconds},
                         {"seconds", r.seconds},
                         {"paper", nullptr},
                         {"faster", nullptr}};
  if (p) {
    line["paper"] = {{"name", p->name},          {"keys", p->keys},
                     {"vertices_in", p->verticesIn}, {"vertices_out", p->verticesOut},
                     {"triangles_in", p->trianglesIn}, {"triangles_out", p->trianglesOut},
                     {"cohesive_in", p->cohesiveIn}, {"cohesive_out", p->cohesiveOut},
                     {"inner", p->inner},        {"outer", p->outer},
                     {"flip_seconds", p->flipSeconds}, {"collapse_seconds", p->collapseSeconds},
                     {"split_seconds", p->splitSeconds}, {"seconds", p->seconds}};
    line["faster"] = r.seconds < p->seconds;
  }
  return line;
}

bool animationCurve(const Timeline& timeline) {
  for (const TimelineSegment& s : timeline.segments())
    if (s.easing.kind != EaseKind::kLinear || !s.controls.empty()) return true;
  return false;
}

nlohmann::json animationTable(const std::string& name, const Scene& scene, const Multimesh& mesh, int threads,
                              const std::optional<PaperRow>& p, cli::Progress& progress) {
  FrameOptions options;
  options.solver.threads = threads;
  FrameStream stream = sceneFrameStream(scene, mesh, options);
  int mostIterations = 0;
  double slowestIteration = 0;
  while (!stream.done()) {
    const AnimationFrame frame = stream.next();
    mostIterations = std::max(mostIterations, frame.iterations);
    if (frame.iterations > 0) slowestIteration = std::max(slowestIteration, frame.milliseconds / frame.iterations);
    progress.update(name + ": frame " + std::to_string(frame.index + 1) + " of " + std::to_string(stream.frameCount()),
                    0.5 + 0.5 * (frame.index + 1.0) / stream.frameCount());
  }
  nlohmann::json line = {{"table", 3},
                         {"scene", name},
                         {"vertices", mesh.vertexCount()},
                         {"frames", stream.frameCount()},
                         {"max_iterations_per_frame", mostIterations},
                         {"max_iteration_ms", slowestIteration},
                         {"epsilon", scene.dynamics.epsilon},
                         {"tau", scene.interpolation.cohesive.tau},
                         {"lambda", scene.interpolation.cohesive.lambda},
                         {"alpha", scene.interpolation.cohesive.alpha},
                         {"mu", scene.dynamics.mu},
                         {"non_overlap", scene.interpolation.nonOverlap},
                         {"uniform_material", scene.stiffness.empty()},
                         {"animation_curve", animationCurve(scene.timeline)},
                         {"paper", nullptr},
                         {"faster", nullptr}};
  if (p) {
    line["paper"] = {{"name", p->name}, {"iterations", p->iterations}, {"local_step_seconds", p->localSeconds},
                     {"global_step_ms", p->globalMs}};
    line["faster"] = slowestIteration < 1000 * p->localSeconds + p->globalMs;
  }
  return line;
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("examples");
  const int threads = cli::integerList(a.value("threads", "0"), "threads", 0, cli::kMaxThreads).front();
  const std::string only = a.value("only", "");
  if (!std::filesystem::is_directory(assets)) throw InputError("bench examples: --assets: " + assets.string() + " is not a folder");
  int measured = 0;
  for (const Example& example : examples()) {
    if (!only.empty() && only != example.folder) continue;
    const std::filesystem::path file = assets / example.folder / "scene.json";
    if (!std::filesystem::exists(file)) {
      if (!only.empty()) throw InputError("bench examples: --only: no " + file.string());
      continue;
    }
    cli::Progress progress;
    progress.update(std::string(example.folder) + ": building the multimesh", 0);
    const Scene scene = loadScene(file.string());
    SceneMultimeshOptions meshOptions;
    meshOptions.useCache = false;  // from the drawings: a .ibmesh left in DIR must not change the figures
    const SceneMultimesh built = sceneMultimesh(scene, meshOptions, [&](const std::string& stage, double fraction) {
      progress.update(std::string(example.folder) + ": " + stage, 0.5 * fraction);
    });
    output.printLine(comeshTable(example.folder, *built.comesh, example.paper));
    const nlohmann::json animation = animationTable(example.folder, scene, *built.multimesh, threads, example.paper, progress);
    progress.finish();
    output.printLine(animation);
    ++measured;
  }
  if (measured == 0)
    throw InputError("bench examples: --assets: none of the paper's examples (e.g. " + assets.string() +
                     "/cell-splitting/scene.json) is there" + (only.empty() ? "" : " named " + only));
}

}  // namespace

Benchmark examplesBenchmark() {
  return {"examples", "the paper's examples, as its Tables 2 and 3", kUsage, {"assets", "only", "threads"}, {}, run};
}

}  // namespace ib
