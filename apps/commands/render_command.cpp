#include "commands/render_command.h"

#include "commands/output_folder.h"
#include "commands/render_options.h"
#include "commands/scene_overrides.h"
#include "core/error.h"
#include "multimesh/multimesh.h"
#include "pipeline/artwork_sampling.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "renderers/render_job.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <stdexcept>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween render SCENE -o DIR [--frames A:B] [--size WxH] [--set NAME=VALUE]... [options]\n"
    "\n"
    "Plays the scene's timeline and renders every frame headless (Vulkan; lavapipe without a GPU):\n"
    "each key's drawing textured onto the deforming mesh, blended by the weights. Writes\n"
    "DIR/frame_NNNN.png (straight alpha), DIR/contact_sheet.png and, with --preview, DIR/preview.png.\n"
    "\n"
    "  -o, --output DIR     folder for the frames, created if missing (and removed again if the\n"
    "                       command fails)\n"
    "  --frames A:B         frames A to B inclusive (or one frame A); default all\n"
    "  --size WxH           picture size in pixels; default the canvas's size (one pixel per drawing\n"
    "                       pixel)\n"
    "  --canvas C           what the frames show: drawing (the drawings' canvas, the default: frames\n"
    "                       line up with the drawings), fit (the whole animation, 8 px round it) or\n"
    "                       WxH+X+Y in drawing pixels (e.g. 640x480-64+0); frames that reach past\n"
    "                       it are noted, with how many and which\n"
    "  --set NAME=VALUE     a parameter instead of the scene's (repeatable): any of `inbetween\n"
    "                       parameters`, e.g. --set tau=1e-5 --set metric=per_key\n"
    "  --fps N              frame rate, the same as --set fps=N; default the scene's timeline's (24)\n"
    "  --background C       transparent (default), or a colour RRGGBB / RRGGBBAA\n"
    "  --samples N          multisample anti-aliasing samples (default 4)\n"
    "  --sampling S         how the drawings' texels are filtered, the same as --set sampling=S:\n"
    "                       linear (trilinear), nearest (magnified pixel art stays crisp) or auto\n"
    "                       (nearest when every drawing is pixel art); default the scene's\n"
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

// Where the multimesh came from, for the summary line.
std::string describeSource(const SceneMultimesh& mesh) {
  if (mesh.source != MeshSource::kBuilt) return mesh.file;
  return mesh.comesh ? "built (with Comesh Optimization)" : "built (initial map)";
}

// --frames within the timeline, --sheet-frames within --frames.
void checkFrames(const std::array<int, 2>& frames, const std::vector<int>& sheetFrames, int frameCount) {
  cli::checkFramesInTimeline(frames, frameCount);
  for (const int f : sheetFrames)
    if (f < frames[0] || f > frames[1])
      throw InputError("--sheet-frames: frame " + std::to_string(f) + " is not rendered (frames " + std::to_string(frames[0]) +
                       ".." + std::to_string(frames[1]) + "): choose frames within --frames");
}

}  // namespace

int runRender(const std::vector<std::string>& rawArgs) {
  const cli::SplitSets split = cli::takeSets(cli::expandShortOutput(rawArgs), "render");
  if (cli::printHelpIfAsked(split.rest, kUsage)) return 0;
  const cli::Arguments arguments("render", split.rest,
                                 {"output", "frames", "size", "canvas", "fps", "background", "samples", "sampling", "onion", "sheet-every",
                                  "sheet-frames", "sheet-columns", "mesh", "device", "threads"},
                                 {"wireframe", "cohesive", "features", "no-comesh", "validation", "preview"});
  if (arguments.positional().size() != 1) throw InputError("render: needs exactly one SCENE file (see `inbetween render --help`)");
  const std::string scenePath = arguments.positional()[0];
  RenderOptions options = parseRenderOptions(arguments);
  std::vector<std::string> sets = split.sets;
  if (arguments.has("fps")) sets.push_back(cli::optionAsSet("--fps", arguments.value("fps", ""), "fps"));
  if (arguments.has("sampling")) sets.push_back(cli::optionAsSet("--sampling", arguments.value("sampling", ""), "sampling"));
  const SceneDocument document = cli::sceneDocument(scenePath, sets);
  const Scene& scene = document.scene();
  if (cli::changesMultimesh(sets, options.mesh.meshFile)) options.mesh.useCache = false;  // the cache is of the file's parameters
  options.mesh.threads = options.threads;
  std::vector<RgbaImage> drawings = readKeyDrawings(scene);
  render::RenderJobOptions job;
  job.sampling = nearestSampling(scene, drawings) ? render::Sampling::kNearest : render::Sampling::kLinear;
  job.frames = options.frames.value_or(std::array<int, 2>{0, scene.timeline.frameCount() - 1});
  checkFrames(job.frames, options.sheetFrames, scene.timeline.frameCount());  // before the long work: fail fast
  vk::ContextOptions contextOptions;
  contextOptions.validation = options.validation;
  contextOptions.device = options.device;
  const vk::VulkanContext context = openVulkan(contextOptions, "render");  // before the long work: fail fast
  cli::OutputFolder folder(options.output, "-o");  // before the long work too

  cli::Progress progress;
  const SceneMultimesh built =
      sceneMultimesh(scene, options.mesh, [&](const std::string& stage, double fraction) { progress.update(stage, 0.3 * fraction); });
  job.folder = folder.path().string();
  job.target = options.target;
  job.target.width = options.size ? (*options.size)[0] : 0;  // 0 x 0: the canvas at one pixel per drawing pixel
  job.target.height = options.size ? (*options.size)[1] : 0;
  job.canvas = options.canvas;
  job.overlays = options.overlays;
  job.onion = options.onion;
  job.sheetEvery = options.sheetEvery;
  job.sheetFrames = options.sheetFrames;
  job.sheetColumns = options.sheetColumns;
  job.preview = options.preview;
  job.solving.solver.threads = options.threads;
  const render::RenderJobReport report =
      render::renderFrames(context, scene, *built.multimesh, std::move(drawings), featureVertices(scene, *built.multimesh), job,
                           [&](const std::string& stage, double fraction) { progress.update(stage, 0.3 + 0.7 * fraction); });
  progress.finish();
  for (const std::string& note : built.notes) std::fprintf(stderr, "inbetween: note: %s\n", note.c_str());
  const std::string reach = report.reach.message(report.written);
  if (!reach.empty()) std::fprintf(stderr, "inbetween: note: %s\n", reach.c_str());
  if (options.validation && !context.validationMessages().empty())
    throw std::runtime_error("render: the validation layer reported: " + context.validationMessages().front());
  folder.keep();
  std::printf("%s: rendered frames %d..%d (%dx%d, %g fps timeline) on %s in %.2f s (%.1f frames/s); multimesh %s\n",
              scenePath.c_str(), job.frames[0], job.frames[1], report.width, report.height, scene.timeline.fps(), context.deviceName().c_str(),
              report.seconds, report.written / report.seconds, describeSource(built).c_str());
  const std::string frames = job.frames[0] == job.frames[1] ? report.firstFrame : report.firstFrame + " .. " + report.lastFrame;
  std::printf("wrote %s and %s%s\n", frames.c_str(), report.sheet.c_str(), options.preview ? (" and " + report.preview).c_str() : "");
  return 0;
}

}  // namespace ib
