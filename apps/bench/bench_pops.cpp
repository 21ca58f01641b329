// `inbetween bench pops`: where the shape jumps from one frame to the next as a scene plays, above
// all where its cuts let go or glue (../shared/topology-change.md): one JSON line per moving
// segment of each scene's timeline.
#include "animation/frame_changes.h"
#include "bench/bench.h"

#include "core/error.h"
#include "pipeline/scene_frames.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "scene/scene.h"

#include <filesystem>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench pops [--assets DIR] [--scenes LIST] [--all] [--threads N]\n"
    "\n"
    "Plays each scene's timeline as `inbetween render` does (from a multimesh built as `inbetween mesh`\n"
    "builds it, never from a cache) and measures every frame-to-frame step. One JSON line per moving\n"
    "segment (between two marks whose weights differ): scene, segment, from and to (the marks' keys),\n"
    "frames (its first frame and steps), cuts (the scene's), then for the silhouette (the mesh's\n"
    "coverage at 1 drawing px) pop = the largest step's changed pixels over the segment's median,\n"
    "pop_frame, pop_share (that step's changed pixels over the silhouette before it), and the same\n"
    "for the vertex RMS move, rms_pop and rms_pop_frame; timing_pop, what the segment's timing alone\n"
    "gives (its largest step of the weights over their median: an eased segment moves unevenly\n"
    "whatever the shapes do); min_area_ratio (a frame's area over the\n"
    "area interpolated between the keys, sum_k w_k area(X_k)) and its frame; releases and glues (the\n"
    "frames where fewer or more cohesive pairs hold than on the frame before); pixel_steps and rms_steps,\n"
    "every step's changed pixels and RMS move (px) from the first frame on. A smooth segment has\n"
    "pops near 1 (eased timing makes them up to about 2).\n"
    "\n"
    "  --assets DIR    folder of scenes, each DIR/NAME/scene.json (default: the bundled scenes)\n"
    "  --scenes LIST   just these scenes of DIR, by folder name, comma-separated (default: those with a cut)\n"
    "  --all           every scene of DIR, with a cut or not\n"
    "  --threads N     solver threads, 0 = all cores (default 0)\n";

int cutCount(const Scene& scene) {
  int cuts = 0;
  for (const KeySpec& key : scene.keys) cuts += static_cast<int>(key.cuts.size());
  return cuts;
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("pops");
  const std::vector<std::string> only = a.has("scenes") ? cli::wordList(a.value("scenes", ""), "--scenes") : std::vector<std::string>{};
  const int threads = a.integer("threads", 0, 0, cli::kMaxThreads);
  for (const auto& file : benchScenes(assets, only, "pops")) {
    const Scene scene = loadScene(file.string());
    const int cuts = cutCount(scene);
    if (cuts == 0 && only.empty() && !a.flag("all")) continue;
    const std::string name = file.parent_path().filename().string();
    cli::Progress progress;
    const auto built = builtFromDrawings(scene, threads, name, progress, 1);
    const Multimesh& mesh = *built.multimesh;
    FrameOptions frameOptions;
    frameOptions.solver.threads = threads;
    FrameStream stream = sceneFrameStream(scene, mesh, frameOptions);
    std::vector<AnimationFrame> frames;
    while (!stream.done()) {
      progress.update(name + ": frames", static_cast<double>(frames.size()) / stream.frameCount());
      frames.push_back(stream.next());
    }
    progress.finish();
    // A loop plays its first frame again after its last: that step is the closing segment's end.
    if (scene.timeline.loops() && !frames.empty()) frames.push_back(frames.front());
    const auto& marks = scene.timeline.marks();
    for (const SegmentChanges& s : segmentChanges(mesh, scene.timeline, frames)) {
      const auto ratio = [](double max, double median) { return median > 0 ? max / median : (max > 0 ? 1e9 : 1.0); };
      output.printLine({{"scene", name},
                        {"segment", s.segment},
                        {"from", marks[s.segment].label},
                        {"to", marks[s.segment + 1].label},
                        {"first_frame", s.firstFrame},
                        {"steps", s.steps},
                        {"cuts", cuts},
                        {"pop", ratio(s.maxPixels, s.medianPixels)},
                        {"pop_frame", s.maxPixelsFrame},
                        {"pop_share", s.maxPixelsShare},
                        {"rms_pop", ratio(s.maxRms, s.medianRms)},
                        {"rms_pop_frame", s.maxRmsFrame},
                        {"timing_pop", s.timingPop},
                        {"min_area_ratio", s.minAreaRatio},
                        {"min_area_frame", s.minAreaFrame},
                        {"releases", s.releases},
                        {"glues", s.glues},
                        {"pixel_steps", s.pixelSteps},
                        {"rms_steps", s.rmsSteps}});
    }
  }
}

}  // namespace

Benchmark popsBenchmark() {
  return {"pops", "where the shape jumps between frames, above all where cuts let go or glue", kUsage,
          {"assets", "scenes", "threads"}, {"all"}, run};
}

}  // namespace ib
