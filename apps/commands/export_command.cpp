#include "commands/export_command.h"

#include "cli.h"
#include "commands/output_folder.h"
#include "commands/scene_overrides.h"
#include "core/error.h"
#include "export/export_job.h"
#include "multimesh/multimesh.h"
#include "pipeline/artwork_sampling.h"
#include "pipeline/key_drawings.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween export SCENE -o OUT.glb|OUT.gltf [--frames A:B] [--max-error PX] [--set NAME=VALUE]... [options]\n"
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
    "  --set NAME=VALUE     a parameter instead of the scene's (repeatable): any of `inbetween\n"
    "                       parameters`, e.g. --set tau=1e-5\n"
    "  --fps N              frame rate, the same as --set fps=N; default the scene's timeline's (24)\n"
    "  --max-error PX       drop the frames a client rebuilds within PX drawing pixels at every\n"
    "                       vertex and every frame time (e.g. 0.25); default: keep every frame\n"
    "  --quantize           16-bit morph targets and UVs (KHR_mesh_quantization, then required)\n"
    "  --meshopt            meshopt-compressed buffers (EXT_meshopt_compression, then required;\n"
    "                       implies --quantize): three.js needs GLTFLoader.setMeshoptDecoder\n"
    "  --pixels-per-unit P  drawing pixels per glTF unit (metre); default 100\n"
    "  --sampling S         texture filtering, the same as --set sampling=S: linear, nearest (pixel\n"
    "                       art) or auto (nearest when every drawing is pixel art); default the scene's\n"
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
  const cli::SplitSets split = cli::takeSets(cli::expandShortOutput(rawArgs), "export");
  if (cli::printHelpIfAsked(split.rest, kUsage)) return 0;
  const cli::Arguments arguments("export", split.rest,
                                 {"output", "frames", "fps", "max-error", "pixels-per-unit", "sampling", "mesh", "threads"},
                                 {"quantize", "meshopt", "no-comesh"});
  if (arguments.positional().size() != 1) throw InputError("export: needs exactly one SCENE file (see `inbetween export --help`)");
  if (!arguments.has("output")) throw InputError("export: needs -o OUT.glb or -o OUT.gltf, the file to write");
  const std::string scenePath = arguments.positional()[0];
  const std::string output = arguments.value("output", "");
  gltf::ExportJobOptions job;
  if (arguments.has("max-error"))
    job.gltf.maxError = cli::positiveNumber(arguments.value("max-error", ""), "--max-error", 1000, "a distance in drawing pixels");
  if (arguments.has("pixels-per-unit"))
    job.gltf.pixelsPerUnit = cli::positiveNumber(arguments.value("pixels-per-unit", ""), "--pixels-per-unit", 1e6, "a scale");
  job.gltf.quantize = arguments.flag("quantize");
  job.gltf.meshopt = arguments.flag("meshopt");
  job.solving.solver.threads = arguments.integer("threads", 0, 0, cli::kMaxThreads);
  SceneMultimeshOptions meshOptions;
  meshOptions.meshFile = arguments.value("mesh", "");
  meshOptions.comesh = !arguments.flag("no-comesh");
  std::vector<std::string> sets = split.sets;
  if (arguments.has("fps")) sets.push_back(cli::optionAsSet("--fps", arguments.value("fps", ""), "fps"));
  if (arguments.has("sampling")) sets.push_back(cli::optionAsSet("--sampling", arguments.value("sampling", ""), "sampling"));
  if (cli::changesMultimesh(sets, meshOptions.meshFile)) meshOptions.useCache = false;  // the cache is of the file's parameters
  meshOptions.threads = job.solving.solver.threads;

  gltf::checkGltfPath(output, "-o");  // before the long work: fail fast on a wrong name
  const SceneDocument document = cli::sceneDocument(scenePath, sets);
  const Scene& scene = document.scene();
  // Printed once the export succeeded: a failed run says one thing, its error.
  const std::vector<std::string> notes = sceneNotes(scene);
  std::vector<RgbaImage> drawings = readKeyDrawings(scene);
  job.gltf.sampling = nearestSampling(scene, drawings) ? render::Sampling::kNearest : render::Sampling::kLinear;
  job.frames = arguments.has("frames") ? cli::frameRange(arguments.value("frames", ""), "--frames")
                                       : std::array<int, 2>{0, scene.timeline.frameCount() - 1};
  cli::checkFramesInTimeline(job.frames, scene.timeline.frameCount());
  job.name = fs::path(scene.file).parent_path().filename().string();
  if (job.name.empty() || job.name == "." || job.name == "..") job.name = fs::path(scene.file).stem().string();
  const fs::path parent = fs::path(output).parent_path();
  std::optional<cli::OutputFolder> folder;
  if (!parent.empty()) folder.emplace(parent.string(), "-o");  // created now, removed again on failure

  cli::Progress progress;
  const auto started = std::chrono::steady_clock::now();
  const std::shared_ptr<const Multimesh> played =
      sceneMultimesh(scene, meshOptions, [&](const std::string& stage, double fraction) { progress.update(stage, 0.3 * fraction); })
          .multimesh;
  const gltf::GltfExportReport report =
      gltf::exportAnimation(scene, *played, std::move(drawings), output, job,
                            [&](const std::string& stage, double fraction) { progress.update(stage, 0.3 + 0.7 * fraction); });
  progress.finish();
  if (folder) folder->keep();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("%s: exported frames %d..%d (%d frame%s at %g fps, %d morph target%s, %d layer%s) in %.2f s\n", scenePath.c_str(),
              job.frames[0], job.frames[1], report.frames, report.frames == 1 ? "" : "s", scene.timeline.fps(), report.targets,
              report.targets == 1 ? "" : "s", report.layers, report.layers == 1 ? "" : "s", seconds);
  std::printf("largest vertex error at any frame time: %.3g drawing pixels (%.2g shape sizes)\n", report.maxError,
              report.maxError / report.shapeSize);
  std::printf("size: %s (%zu bytes); every frame as 32-bit floats: %s (%zu bytes)\n", humanBytes(report.bytes).c_str(),
              report.bytes, humanBytes(report.bytesRaw).c_str(), report.bytesRaw);
  std::printf("wrote %s\n", output.c_str());
  for (const std::string& note : notes) std::fprintf(stderr, "inbetween: note: %s\n", note.c_str());
  return 0;
}

}  // namespace ib
