#include "commands/export_command.h"

#include "animation/frame_stream.h"
#include "cli.h"
#include "commands/output_folder.h"
#include "core/error.h"
#include "export/baked_animation.h"
#include "export/gltf_export.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "output/render_mesh.h"
#include "pipeline/artwork_sampling.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "scene/scene.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween export SCENE -o OUT.glb|OUT.gltf [--fps N] [--frames A:B] [--max-error PX] [options]\n"
    "\n"
    "Bakes the scene's timeline (dynamics included) into a glTF 2.0 animation for game engines and\n"
    "the web: one mesh whose morph targets are the frames, welded where the cuts hold, played by a\n"
    "weights animation with at most two targets active; one layer per key drawing (embedded PNG,\n"
    "alpha blended, unlit), cross-faded by the interpolation weights through KHR_animation_pointer.\n"
    "A client without that extension shows the first frame's drawing throughout. See docs/export.md.\n"
    "\n"
    "  -o, --output FILE    .glb (one binary file) or .gltf (JSON, with FILE's name .bin beside it);\n"
    "                       written atomically, a missing folder is created\n"
    "  --frames A:B         frames A to B inclusive (or one frame A); default all\n"
    "  --fps N              frame rate; default the scene's timeline's (24 without one)\n"
    "  --max-error PX       drop the frames a client rebuilds within PX drawing pixels at every\n"
    "                       vertex and every frame time (e.g. 0.25); default: keep every frame\n"
    "  --quantize           16-bit morph targets and UVs (KHR_mesh_quantization, then required)\n"
    "  --meshopt            meshopt-compressed buffers (EXT_meshopt_compression, then required;\n"
    "                       implies --quantize): three.js needs GLTFLoader.setMeshoptDecoder\n"
    "  --pixels-per-unit P  drawing pixels per glTF unit (metre); default 100\n"
    "  --sampling S         texture filtering: linear or nearest (pixel art); default the scene's\n"
    "                       \"sampling\" (auto: nearest when every drawing is pixel art, else linear)\n"
    "  --mesh FILE          multimesh to use (default: SCENE's .ibmesh from `inbetween mesh` when\n"
    "                       newer than the scene and drawings, else built now)\n"
    "  --no-comesh          when building the multimesh, skip Comesh Optimization\n"
    "  --threads N          the most solver threads, 0 = all cores (default); fewer run while other\n"
    "                       programs keep cores busy\n";

namespace fs = std::filesystem;

std::string humanBytes(size_t bytes) {
  char text[32];
  if (bytes < 10 * 1024) std::snprintf(text, sizeof text, "%zu B", bytes);
  else if (bytes < 10 * 1024 * 1024) std::snprintf(text, sizeof text, "%.1f KiB", bytes / 1024.0);
  else std::snprintf(text, sizeof text, "%.1f MiB", bytes / (1024.0 * 1024.0));
  return text;
}

}  // namespace

int runExport(const std::vector<std::string>& rawArgs) {
  const std::vector<std::string> args = cli::expandShortOutput(rawArgs);
  if (cli::printHelpIfAsked(args, kUsage)) return 0;
  const cli::Arguments arguments("export", args,
                                 {"output", "frames", "fps", "max-error", "pixels-per-unit", "sampling", "mesh", "threads"},
                                 {"quantize", "meshopt", "no-comesh"});
  if (arguments.positional().size() != 1) throw InputError("export: needs exactly one SCENE file (see `inbetween export --help`)");
  if (!arguments.has("output")) throw InputError("export: needs -o OUT.glb or -o OUT.gltf, the file to write");
  const std::string scenePath = arguments.positional()[0];
  const std::string output = arguments.value("output", "");
  gltf::GltfExportOptions options;
  if (arguments.has("max-error"))
    options.maxError = cli::positiveNumber(arguments.value("max-error", ""), "--max-error", 1000, "a distance in drawing pixels");
  if (arguments.has("pixels-per-unit"))
    options.pixelsPerUnit = cli::positiveNumber(arguments.value("pixels-per-unit", ""), "--pixels-per-unit", 1e6, "a scale");
  options.quantize = arguments.flag("quantize");
  options.meshopt = arguments.flag("meshopt");
  std::optional<render::Sampling> sampling;  // default: the scene's "sampling", once its drawings are read
  if (arguments.has("sampling")) {
    const std::string text = arguments.value("sampling", "");
    if (text == "nearest") sampling = render::Sampling::kNearest;
    else if (text == "linear") sampling = render::Sampling::kLinear;
    else throw InputError("--sampling: '" + text + "' is not linear or nearest");
  }
  SceneMultimeshOptions meshOptions;
  meshOptions.meshFile = arguments.value("mesh", "");
  meshOptions.comesh = !arguments.flag("no-comesh");
  SolverOptions solver;
  solver.threads = arguments.integer("threads", 0, 0, 256);

  gltf::checkGltfPath(output, "-o");  // before the long work: fail fast on a wrong name
  const Scene scene = loadScene(scenePath);
  // Printed once the export succeeded: a failed run says one thing, its error.
  const std::vector<std::string> notes = sceneNotes(scene);
  std::vector<RgbaImage> drawings = readKeyDrawings(scene);
  options.sampling = sampling.value_or(nearestSampling(scene, drawings) ? render::Sampling::kNearest : render::Sampling::kLinear);
  Timeline timeline = scene.timeline;
  if (arguments.has("fps"))
    timeline = Timeline(cli::positiveNumber(arguments.value("fps", ""), "--fps", 1000, "a frame rate"), timeline.loops(),
                        timeline.marks(), timeline.segments());
  const int frameCount = timeline.frameCount();
  const std::array<int, 2> range =
      arguments.has("frames") ? cli::frameRange(arguments.value("frames", ""), "--frames") : std::array<int, 2>{0, frameCount - 1};
  if (range[1] >= frameCount)
    throw InputError("--frames: the timeline has frames 0.." + std::to_string(frameCount - 1) + ", asked for up to " +
                     std::to_string(range[1]));
  const fs::path parent = fs::path(output).parent_path();
  std::optional<cli::OutputFolder> folder;
  if (!parent.empty()) folder.emplace(parent.string(), "-o");  // created now, removed again on failure

  cli::Progress progress;
  const auto started = std::chrono::steady_clock::now();
  const std::shared_ptr<const Multimesh> played =
      sceneMultimesh(scene, meshOptions, [&](const std::string& stage, double fraction) { progress.update(stage, 0.3 * fraction); })
          .multimesh;
  // Every frame a 32-bit float target of 12 bytes per vertex: refuse before solving what no glTF
  // container holds (--max-error and --meshopt shrink it only afterwards, by an amount unknown yet).
  const double targetBytes = 12.0 * played->vertexCount() * (range[1] - range[0] + 1);
  if (targetBytes > 3.5 * 1024 * 1024 * 1024)
    throw InputError("export: " + std::to_string(range[1] - range[0] + 1) + " frames of " + std::to_string(played->vertexCount()) +
                     " vertices would be " + std::to_string(static_cast<long long>(targetBytes / (1 << 20))) +
                     " MiB of morph targets, more than a glTF file holds: export fewer frames (--frames) or mesh coarser "
                     "(a larger \"edge_length\" in " + scene.file + ")");
  gltf::ExportedScene exported;
  exported.name = fs::path(scene.file).parent_path().filename().string();
  if (exported.name.empty() || exported.name == "." || exported.name == "..") exported.name = fs::path(scene.file).stem().string();
  for (const KeySpec& key : scene.keys) exported.keyNames.push_back(key.name);
  for (const RgbaImage& d : drawings) {
    exported.canvas[0] = std::max(exported.canvas[0], d.width);
    exported.canvas[1] = std::max(exported.canvas[1], d.height);
  }
  const render::RenderMesh mesh = render::renderMeshOf(*played, std::move(drawings));
  FrameStream stream(*played, timeline, interpolationParams(scene.solver), solver, scene.dynamics);
  const gltf::BakedAnimation baked = gltf::bakeAnimation(stream, mesh.cutSides, range, [&](int done, int total) {
    progress.update("solving frame " + std::to_string(done - 1) + " (" + std::to_string(done) + " of " + std::to_string(total) + ")",
                    0.3 + 0.6 * done / total);
  });
  progress.update("writing " + output, 0.95);
  const gltf::GltfExportReport report = gltf::writeGltf(baked, mesh, exported, options, output);
  progress.finish();
  if (folder) folder->keep();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("%s: exported frames %d..%d (%d frame%s at %g fps, %d morph target%s, %d layer%s) in %.2f s\n", scenePath.c_str(),
              range[0], range[1], report.frames, report.frames == 1 ? "" : "s", timeline.fps(), report.targets,
              report.targets == 1 ? "" : "s", report.layers, report.layers == 1 ? "" : "s", seconds);
  std::printf("largest vertex error at any frame time: %.3g drawing pixels (%.2g shape sizes)\n", report.maxError,
              report.maxError / baked.shapeSize);
  std::printf("size: %s (%zu bytes); every frame as 32-bit floats: %s (%zu bytes)\n", humanBytes(report.bytes).c_str(),
              report.bytes, humanBytes(report.bytesRaw).c_str(), report.bytesRaw);
  std::printf("wrote %s\n", output.c_str());
  for (const std::string& note : notes) std::fprintf(stderr, "inbetween: note: %s\n", note.c_str());
  return 0;
}

}  // namespace ib
