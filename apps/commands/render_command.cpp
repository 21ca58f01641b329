#include "commands/render_command.h"

#include "animation/frame_stream.h"
#include "commands/output_folder.h"
#include "commands/render_options.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "gpu/vulkan_check.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "output/animated_png.h"
#include "output/contact_sheet.h"
#include "output/onion_window.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "scene/scene.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween render SCENE -o DIR [--frames A:B] [--size WxH] [--fps N] [options]\n"
    "\n"
    "Plays the scene's timeline and renders every frame headless (Vulkan; lavapipe without a GPU):\n"
    "each key's drawing textured onto the deforming mesh, blended by the weights. Writes\n"
    "DIR/frame_NNNN.png (straight alpha), DIR/contact_sheet.png and, with --preview, DIR/preview.png.\n"
    "\n"
    "  -o, --output DIR     folder for the frames, created if missing (and removed again if the\n"
    "                       command fails)\n"
    "  --frames A:B         frames A to B inclusive (or one frame A); default all\n"
    "  --size WxH           picture size in pixels; default the drawings' size\n"
    "  --fps N              frame rate; default the scene's timeline's (24 without one)\n"
    "  --background C       transparent (default), or a colour RRGGBB / RRGGBBAA\n"
    "  --samples N          multisample anti-aliasing samples (default 4)\n"
    "  --sampling S         how the drawings' texels are filtered: linear (trilinear) or nearest\n"
    "                       (magnified pixel art stays crisp); default the scene's \"sampling\"\n"
    "                       (auto: nearest when every drawing is pixel art, else linear)\n"
    "  --wireframe          draw the mesh's edges\n"
    "  --cohesive           draw the cohesive edges of the keys in play, red\n"
    "  --features           draw the feature vertices, blue\n"
    "  --onion N            onion skins: N neighbouring frames each side, faded (0..2, default 0)\n"
    "  --sheet-every K      every K-th frame on the contact sheet (default: at most 36 tiles)\n"
    "  --sheet-frames LIST  just these frames on the contact sheet, e.g. 0,12,18,24 (each rendered)\n"
    "  --sheet-columns N    tiles per row of the contact sheet (default: about square)\n"
    "  --preview            also DIR/preview.png: every frame at the contact sheet's tile size (240 px\n"
    "                       wide at most), an animated PNG (APNG) that loops at the timeline's rate\n"
    "  --mesh FILE          multimesh to use (default: SCENE's .ibmesh from `inbetween mesh` when\n"
    "                       newer than the scene and drawings, else built now)\n"
    "  --no-comesh          when building the multimesh, skip Comesh Optimization\n"
    "  --device D           any (default: a GPU if present, else lavapipe), gpu or cpu\n"
    "  --validation         run with the Khronos validation layer; any message is an error\n"
    "  --threads N          the most solver threads, 0 = all cores (default); fewer run while the\n"
    "                       rasterizer or other programs keep cores busy\n";

namespace fs = std::filesystem;

Timeline withFps(const Timeline& timeline, double fps) {
  return Timeline(fps, timeline.loops(), timeline.marks(), timeline.segments());
}

std::string framePath(const fs::path& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", frame);
  return (dir / name).string();
}

// Where the multimesh came from, for the summary line.
std::string describeSource(const SceneMultimesh& mesh) {
  if (mesh.source != MeshSource::kBuilt) return mesh.file;
  return mesh.comesh ? "built (with Comesh Optimization)" : "built (initial map)";
}

}  // namespace

int runRender(const std::vector<std::string>& rawArgs) {
  const std::vector<std::string> args = cli::expandShortOutput(rawArgs);
  if (cli::printHelpIfAsked(args, kUsage)) return 0;
  const cli::Arguments arguments("render", args,
                                 {"output", "frames", "size", "fps", "background", "samples", "sampling", "onion", "sheet-every",
                                  "sheet-frames", "sheet-columns",
                                  "mesh", "device", "threads"},
                                 {"wireframe", "cohesive", "features", "no-comesh", "validation", "preview"});
  if (arguments.positional().size() != 1) throw InputError("render: needs exactly one SCENE file (see `inbetween render --help`)");
  const std::string scenePath = arguments.positional()[0];
  RenderOptions options = parseRenderOptions(arguments);
  const Scene scene = loadScene(scenePath);
  std::vector<RgbaImage> drawings = readKeyDrawings(scene);
  const render::Sampling sampling = sceneSampling(options.sampling, scene, drawings);  // before the drawings move
  const Timeline timeline = options.fps ? withFps(scene.timeline, *options.fps) : scene.timeline;
  const int frameCount = timeline.frameCount();
  const std::array<int, 2> range = options.frames.value_or(std::array<int, 2>{0, frameCount - 1});
  if (range[1] >= frameCount)
    throw InputError("--frames: the timeline has frames 0.." + std::to_string(frameCount - 1) + ", asked for up to " +
                     std::to_string(range[1]));
  for (const int f : options.sheetFrames)
    if (f < range[0] || f > range[1])
      throw InputError("--sheet-frames: frame " + std::to_string(f) + " is not rendered (frames " + std::to_string(range[0]) +
                       ".." + std::to_string(range[1]) + "): choose frames within --frames");
  vk::ContextOptions contextOptions;
  contextOptions.validation = options.validation;
  contextOptions.device = options.device;
  const vk::VulkanContext context = openVulkan(contextOptions, "render");  // before the long work: fail fast
  cli::OutputFolder folder(options.output, "-o");  // before the long work too
  const fs::path& dir = folder.path();

  cli::Progress progress;
  std::string source;
  std::vector<std::string> notes;
  const std::shared_ptr<const Multimesh> played = [&] {  // the build's initial map and report let go here
    const SceneMultimesh built =
        sceneMultimesh(scene, options.mesh, [&](const std::string& stage, double fraction) { progress.update(stage, 0.3 * fraction); });
    source = describeSource(built);
    notes = built.notes;
    return built.multimesh;
  }();
  const Multimesh& mesh = *played;
  int canvasW = 0, canvasH = 0;
  for (const RgbaImage& d : drawings) {
    canvasW = std::max(canvasW, d.width);
    canvasH = std::max(canvasH, d.height);
  }
  const std::array<int, 2> size = options.size.value_or(std::array<int, 2>{canvasW, canvasH});
  options.target.width = size[0];
  options.target.height = size[1];
  const render::RenderMesh renderMesh = render::renderMeshOf(mesh, std::move(drawings), featureVertices(scene, mesh));
  // A target the device has no memory for is the user's size, not an internal error.
  const auto makeRenderer = [&]() {
    try {
      return render::OffscreenRenderer(context, renderMesh, options.target);
    } catch (const vk::VulkanError& e) {
      if (e.result() != VK_ERROR_OUT_OF_DEVICE_MEMORY && e.result() != VK_ERROR_OUT_OF_HOST_MEMORY) throw;
      throw InputError("--size " + std::to_string(size[0]) + "x" + std::to_string(size[1]) + ": " + context.deviceName() +
                       " has not enough memory for a target of that size with " + std::to_string(options.target.samples) +
                       " samples (" + e.what() + "): choose a smaller --size or fewer --samples");
    }
  };
  render::OffscreenRenderer renderer = makeRenderer();
  const render::ViewBox view = render::fitView({0, 0, double(canvasW), double(canvasH)}, size[0], size[1], 0);

  SolverOptions solver;
  solver.threads = options.threads;
  FrameStream stream(mesh, timeline, interpolationParams(scene.solver), solver, scene.dynamics);
  const int rendered = range[1] - range[0] + 1;
  const int every = options.sheetEvery > 0 ? options.sheetEvery : (rendered + 35) / 36;
  auto onSheet = [&](int f) {
    if (!options.sheetFrames.empty())
      return std::binary_search(options.sheetFrames.begin(), options.sheetFrames.end(), f);
    return (f - range[0]) % every == 0;
  };
  const int tileW = std::min(240, size[0]);
  const int tileH = std::max(1, static_cast<int>(std::lround(double(tileW) * size[1] / size[0])));
  std::vector<RgbaImage> tiles, preview;
  std::deque<int> inFlight;           // frame indices submitted, oldest first
  int written = 0;
  const auto started = std::chrono::steady_clock::now();
  auto collect = [&]() {
    const int f = inFlight.front();
    inFlight.pop_front();
    const RgbaImage image = renderer.take();
    writePng(framePath(dir, f), image);
    const bool sheet = onSheet(f);
    if (sheet || options.preview) {
      RgbaImage tile = render::shrink(image, tileW, tileH);
      if (sheet) tiles.push_back(tile);
      if (options.preview) preview.push_back(std::move(tile));
    }
    ++written;
    progress.update("rendering frame " + std::to_string(f) + " (" + std::to_string(written) + " of " + std::to_string(rendered) + ")",
                    0.3 + 0.7 * written / rendered);
  };
  render::OnionStyle onion;
  onion.neighbours = options.onion;
  auto draw = [&](const std::deque<AnimationFrame>& window, size_t at) {
    const AnimationFrame& frame = window[at];
    render::FrameDraw request = render::frameWithOnionSkins(window, at, onion, view, options.overlays);
    request.sampling = sampling;
    renderer.submit(request);
    inFlight.push_back(frame.index);
    while (static_cast<int>(inFlight.size()) > 2) collect();
  };
  render::playWithNeighbours(stream, range, options.onion, draw);
  while (!inFlight.empty()) collect();
  const std::string sheetPath = (dir / "contact_sheet.png").string();
  render::ContactSheetOptions sheet;
  sheet.columns = options.sheetColumns;
  writePng(sheetPath, render::contactSheet(tiles, sheet));
  const std::string previewPath = (dir / "preview.png").string();
  if (options.preview)
    writeFileAtomically(previewPath, render::encodeAnimatedPng(preview, static_cast<int>(std::lround(1000 / timeline.fps()))));
  progress.finish();
  for (const std::string& note : notes) std::fprintf(stderr, "inbetween: note: %s\n", note.c_str());
  if (options.validation && !context.validationMessages().empty())
    throw std::runtime_error("render: the validation layer reported: " + context.validationMessages().front());
  folder.keep();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("%s: rendered frames %d..%d (%dx%d, %g fps timeline) on %s in %.2f s (%.1f frames/s); multimesh %s\n",
              scenePath.c_str(), range[0], range[1], size[0], size[1], timeline.fps(), context.deviceName().c_str(), seconds,
              written / seconds, source.c_str());
  const std::string frames =
      range[0] == range[1] ? framePath(dir, range[0]) : framePath(dir, range[0]) + " .. " + framePath(dir, range[1]);
  std::printf("wrote %s and %s%s\n", frames.c_str(), sheetPath.c_str(), options.preview ? (" and " + previewPath).c_str() : "");
  return 0;
}

}  // namespace ib
