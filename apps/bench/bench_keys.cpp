// `inbetween bench keys`: whether the key frames are the drawings (issue: faithful pixels): one JSON
// line per scene and scale.
#include "bench/bench.h"

#include "commands/render_options.h"
#include "output/key_fidelity.h"
#include "pipeline/artwork_sampling.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "renderers/offscreen_renderer.h"
#include "scene/scene.h"

#include <algorithm>
#include <filesystem>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench keys [--assets DIR] [--scenes LIST] [--scales LIST] [--frames DIR] [--threads N]\n"
    "\n"
    "Builds each scene's multimesh as `inbetween mesh` does (never from a cache), renders every key\n"
    "at its weight e_i and its own positions (which the solver reproduces there) as `inbetween\n"
    "render` draws (4 samples, the scene's sampling, the drawings' canvas) at the drawings' size times\n"
    "each scale, and compares it with the key's drawing magnified by the same sampler (nearest: texel\n"
    "squares; linear: bilinear), in premultiplied RGBA. One JSON line per scene and scale: scene,\n"
    "scale, sampling, keys, pixels (compared, all keys), over_2 (pixels off by more than 2/255), the\n"
    "worst key's share over_2_share_worst, worst (the largest difference, 0-255) and where: worst_key,\n"
    "worst_x, worst_y (frame pixels).\n"
    "\n"
    "  --assets DIR    folder of scenes, each DIR/NAME/scene.json (default: the bundled scenes)\n"
    "  --scenes LIST   just these scenes of DIR, by folder name, comma-separated (default: every one)\n"
    "  --scales LIST   integer magnifications, comma-separated, 1-8 (default 1,2)\n"
    "  --frames DIR    also write each key frame, DIR/SCENE_key_K_xS.png, to look at (DIR is created)\n"
    "  --threads N     solver threads, 0 = all cores (default 0)\n";

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("keys");
  const std::vector<std::string> only = a.has("scenes") ? cli::wordList(a.value("scenes", ""), "--scenes") : std::vector<std::string>{};
  const std::vector<int> scales = cli::integerList(a.value("scales", "1,2"), "scales", 1, 8);
  const int threads = a.integer("threads", 0, 0, cli::kMaxThreads);
  const std::string frames = a.value("frames", "");
  if (!frames.empty()) std::filesystem::create_directories(frames);
  vk::ContextOptions contextOptions;
  const vk::VulkanContext context = openVulkan(contextOptions, "bench keys");
  for (const auto& file : benchScenes(assets, only, "keys")) {
    const Scene scene = loadScene(file.string());
    const std::string name = file.parent_path().filename().string();
    cli::Progress progress;
    const SceneMultimesh built = builtFromDrawings(scene, threads, name, progress, 0.3);
    const std::vector<RgbaImage> drawings = readKeyDrawings(scene);
    const bool nearest = nearestSampling(scene, drawings);
    int canvasW = 1, canvasH = 1;  // the largest drawing's size, as `render`
    for (const RgbaImage& d : drawings) canvasW = std::max(canvasW, d.width), canvasH = std::max(canvasH, d.height);
    render::RenderMesh renderMesh = render::renderMeshOf(*built.multimesh, drawings, featureVertices(scene, *built.multimesh));
    if (!scene.cutInk) renderMesh.inks = {};
    const int keys = built.multimesh->keyCount();
    for (size_t si = 0; si < scales.size(); ++si) {
      const int scale = scales[si];
      render::OffscreenOptions target;
      target.width = canvasW * scale;
      target.height = canvasH * scale;
      target.background = {0, 0, 0, 0};
      render::OffscreenRenderer renderer(context, renderMesh, target);
      long long pixels = 0, over2 = 0;
      double worstShare = 0;
      int worst = 0, worstKey = -1, worstX = -1, worstY = -1;
      for (int k = 0; k < keys; ++k) {
        progress.update(name + ": key " + std::to_string(k) + " at " + std::to_string(scale) + "x",
                        0.3 + 0.7 * (si * keys + k) / double(scales.size() * keys));
        const Eigen::MatrixX2d x = built.multimesh->keyPositions(k);
        render::FrameDraw draw;
        draw.positions = &x;
        draw.weights = Eigen::VectorXd::Unit(keys, k);
        draw.view = render::fitView({0, 0, double(canvasW), double(canvasH)}, target.width, target.height, 0);
        draw.sampling = nearest ? render::Sampling::kNearest : render::Sampling::kLinear;
        const RgbaImage frame = renderer.render(draw);
        const RgbaImage& drawing = drawings[static_cast<size_t>(k)];
        if (!frames.empty())
          writePng((std::filesystem::path(frames) / (name + "_key_" + std::to_string(k) + "_x" + std::to_string(scale) + ".png")).string(),
                   frame);
        const render::KeyFidelity fidelity = render::keyFidelity(frame, drawing, scale, nearest);
        pixels += fidelity.pixels;
        over2 += fidelity.over;
        worstShare = std::max(worstShare, double(fidelity.over) / std::max<long long>(1, fidelity.pixels));
        if (fidelity.worst > worst) worst = fidelity.worst, worstKey = k, worstX = fidelity.worstX, worstY = fidelity.worstY;
      }
      output.printLine({{"scene", name},
                        {"scale", scale},
                        {"sampling", nearest ? "nearest" : "linear"},
                        {"keys", keys},
                        {"pixels", pixels},
                        {"over_2", over2},
                        {"over_2_share_worst", worstShare},
                        {"worst", worst},
                        {"worst_key", worstKey},
                        {"worst_x", worstX},
                        {"worst_y", worstY}});
    }
    progress.finish();
  }
}

}  // namespace

Benchmark keysBenchmark() {
  return {"keys", "whether the key frames are the drawings, pixel for pixel", kUsage, {"assets", "scenes", "scales", "frames", "threads"}, {}, run};
}

}  // namespace ib
