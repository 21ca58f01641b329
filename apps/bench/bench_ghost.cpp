// `inbetween bench ghost`: how far the inbetweens stray from the drawings where the drawings agree
// (../shared/correspondence.md): one JSON line per scene.
#include "bench/bench.h"

#include "commands/render_options.h"
#include "core/error.h"
#include "output/ghosting.h"
#include "pipeline/artwork_sampling.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "renderers/render_job.h"
#include "scene/scene.h"

#include <algorithm>
#include <filesystem>
#include <random>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench ghost [--assets DIR] [--scenes LIST] [--threads N]\n"
    "\n"
    "Builds each scene's multimesh as `inbetween mesh` does (never from a cache), renders its frames as\n"
    "`inbetween render` does (the drawings' size, 4 samples), and compares every inbetween (a frame\n"
    "whose weights are no key's alone) with the drawings where every key's drawing is the same\n"
    "(premultiplied RGBA within 2/255, 3 px from any pixel that differs). One JSON line per scene:\n"
    "scene, keys, frames (inbetweens compared), mask_pixels (where the keys agree; 0: nowhere,\n"
    "nothing measured) and drawn_pixels (those that every key draws, alpha > 0); over all of them,\n"
    "ghost_mean (the worst inbetween's mean difference, largest channel, 0-255) and its frame\n"
    "ghost_mean_frame, ghost_share (the worst share of them off by more than 48/255) and\n"
    "ghost_share_frame; drawn_mean and drawn_share, the same over the drawn pixels alone; notes, the\n"
    "build's (e.g. a \"correspondence\" that could not be mapped, and what was used instead);\n"
    "edge_excess, the most an inbetween's edge pixels inside the shape (a neighbour more than 48/255\n"
    "apart, 4 px or more from the paper) exceed the keys' counts blended by its weights, as a\n"
    "fraction (0.2: a fifth more edges: detail that moved, cross-faded from two places), and its\n"
    "frame edge_excess_frame.\n"
    "\n"
    "  --assets DIR    folder of scenes, each DIR/NAME/scene.json (default: the bundled scenes)\n"
    "  --scenes LIST   just these scenes of DIR, by folder name, comma-separated (default: every one)\n"
    "  --threads N     solver threads, 0 = all cores (default 0)\n";

// The worst inbetween over a mask.
struct Worst {
  double mean = 0, share = 0;
  int meanFrame = -1, shareFrame = -1;
  void add(const render::Ghosting& g, int frame) {
    if (g.pixels == 0) return;
    if (meanFrame < 0 || g.mean > mean) mean = g.mean, meanFrame = frame;
    if (shareFrame < 0 || g.share > share) share = g.share, shareFrame = frame;
  }
};

// A folder in the temporary directory for the frames, removed with everything in it at the end,
// whatever ends the bench.
struct Scratch {
  std::filesystem::path path;
  Scratch() {
    std::mt19937 random(std::random_device{}());
    path = std::filesystem::temp_directory_path() / ("inbetween-bench-ghost-" + std::to_string(random()));
  }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("ghost");
  const std::vector<std::string> only = a.has("scenes") ? cli::wordList(a.value("scenes", ""), "--scenes") : std::vector<std::string>{};
  const int threads = a.integer("threads", 0, 0, cli::kMaxThreads);
  vk::ContextOptions contextOptions;
  const vk::VulkanContext context = openVulkan(contextOptions, "bench ghost");
  const Scratch scratchFolder;
  const std::filesystem::path& scratch = scratchFolder.path;
  for (const auto& file : benchScenes(assets, only, "ghost")) {
    const Scene scene = loadScene(file.string());
    const std::string name = file.parent_path().filename().string();
    cli::Progress progress;
    const SceneMultimesh built = builtFromDrawings(scene, threads, name, progress, 0.3);
    std::vector<RgbaImage> drawings = readKeyDrawings(scene);
    const AgreementMask all = agreement(drawings);
    AgreementOptions drawnOnly;
    drawnOnly.opaqueOnly = true;
    const AgreementMask drawn = agreement(drawings, drawnOnly);

    render::RenderJobOptions job;
    job.sampling = nearestSampling(scene, drawings) ? render::Sampling::kNearest : render::Sampling::kLinear;
    job.frames = {0, scene.timeline.frameCount() - 1};
    job.target.width = job.target.height = 1;  // the largest drawing's size, as `render`
    for (const RgbaImage& d : drawings) {
      job.target.width = std::max(job.target.width, d.width);
      job.target.height = std::max(job.target.height, d.height);
    }
    job.target.background = {0, 0, 0, 0};
    job.solving.solver.threads = threads;
    std::filesystem::remove_all(scratch);
    std::filesystem::create_directories(scratch);
    job.folder = scratch.string();
    const RgbaImage key = drawings.front();
    std::vector<double> keyEdges;
    for (const RgbaImage& d : drawings) keyEdges.push_back(render::edgePixels(d));
    render::renderFrames(context, scene, *built.multimesh, std::move(drawings), featureVertices(scene, *built.multimesh), job,
                         [&](const std::string& stage, double f) { progress.update(name + ": " + stage, 0.3 + 0.7 * f); });
    progress.finish();

    Worst overAll, overDrawn;
    int compared = 0, excessFrame = -1;
    double excess = 0;
    for (int f = 0; f < scene.timeline.frameCount(); ++f) {
      const Eigen::VectorXd w = scene.timeline.weights(scene.timeline.frameTime(f));
      if (w.maxCoeff() > 1 - 1e-9) continue;  // a key frame
      const RgbaImage frame = readPng(render::framePath(scratch.string(), f));
      overAll.add(render::ghosting(frame, key, all), f);
      overDrawn.add(render::ghosting(frame, key, drawn), f);
      double blended = 0;
      for (Eigen::Index k = 0; k < w.size(); ++k) blended += w(k) * keyEdges[static_cast<size_t>(k)];
      const double e = blended > 0 ? render::edgePixels(frame) / blended - 1 : 0;
      if (excessFrame < 0 || e > excess) excess = e, excessFrame = f;
      ++compared;
    }
    output.printLine({{"scene", name},
                      {"keys", static_cast<int>(scene.keys.size())},
                      {"frames", compared},
                      {"mask_pixels", all.count},
                      {"drawn_pixels", drawn.count},
                      {"ghost_mean", overAll.mean},
                      {"ghost_mean_frame", overAll.meanFrame},
                      {"ghost_share", overAll.share},
                      {"ghost_share_frame", overAll.shareFrame},
                      {"drawn_mean", overDrawn.mean},
                      {"drawn_share", overDrawn.share},
                      {"edge_excess", excess},
                      {"edge_excess_frame", excessFrame},
                      {"notes", built.notes}});
  }
}

}  // namespace

Benchmark ghostBenchmark() {
  return {"ghost", "how far inbetweens stray from the drawings where the drawings agree", kUsage, {"assets", "scenes", "threads"}, {}, run};
}

}  // namespace ib
