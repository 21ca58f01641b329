#include "mesh_command.h"

#include "cli.h"
#include "comesh/comesh.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "mesh_report.h"
#include "meshing/multimesh_builder.h"
#include "meshing/stiffness_paint.h"
#include "multimesh/mesh_svg.h"
#include "multimesh/multimesh_io.h"
#include "progress.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <nlohmann/json.hpp>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween mesh SCENE [-o OUT] [--json] [--no-pictures] [--no-comesh]\n"
    "\n"
    "Traces the scene's drawings, applies features and cuts, meshes the reference key, maps the\n"
    "mesh onto every key without foldovers, then improves every key's triangles and every map\n"
    "between keys together (Comesh Optimization). Prints the Comesh statistics and the quality\n"
    "before and after.\n"
    "\n"
    "  -o, --output OUT  multimesh file to write (default: SCENE's folder, SCENE's name .ibmesh);\n"
    "                    the initial map goes next to it as OUT's name .initial.ibmesh\n"
    "  --json            print the summary as one JSON object\n"
    "  --no-pictures     skip the pictures (OUT's name, then .KEY.svg: mesh over drawing,\n"
    "                    cohesive edges red, features as dots)\n"
    "  --no-comesh       write the initial map only, as OUT\n";

namespace fs = std::filesystem;

fs::path besideOutput(const fs::path& output, const std::string& suffix) {
  return output.parent_path() / (output.stem().string() + suffix);
}

// One SVG per key; adds each picture's path to the key's entry in `quality`.
void writePictures(const Scene& scene, const BuiltScene& built, const Multimesh& mesh, const fs::path& output,
                   nlohmann::json& quality) {
  for (size_t k = 0; k < scene.keys.size(); ++k) {
    const fs::path picture = besideOutput(output, "." + scene.keys[k].name + ".svg");
    const auto [width, height] = built.drawingSizes[k];
    writeFileAtomically(picture.string(), meshSvg(mesh, static_cast<int>(k), built.shapes[k],
                                                  readFile(scene.keys[k].drawing), width, height));
    quality["keys"][k]["picture"] = picture.string();
  }
}

}  // namespace

int runMesh(const std::vector<std::string>& rawArgs) {
  const std::vector<std::string> args = cli::expandShortOutput(rawArgs);
  if (cli::printHelpIfAsked(args, kUsage)) return 0;
  const cli::Arguments options("mesh", args, {"output"}, {"json", "no-pictures", "no-comesh"});
  if (options.positional().size() != 1) throw InputError("mesh: needs exactly one SCENE file (see `inbetween mesh --help`)");
  const std::string scenePath = options.positional()[0];
  const Scene scene = loadScene(scenePath);
  const fs::path output = options.value("output", (fs::path(scenePath).parent_path() / fs::path(scenePath).stem()).string() + ".ibmesh");
  const bool comesh = !options.flag("no-comesh");
  std::vector<std::string> names;
  for (const KeySpec& key : scene.keys) names.push_back(key.name);

  cli::Progress progress;
  MultimeshBuildOptions buildOptions;
  const double buildShare = comesh ? 0.3 : 0.9;
  buildOptions.progress = [&](const std::string& stage, double fraction) { progress.update(stage, buildShare * fraction); };
  const BuiltScene built = buildMultimesh(scene, buildOptions);
  nlohmann::json summary{{"scene", scenePath}, {"edge_length", built.edgeLength}};
  summary["initial"] = qualityJson(*built.multimesh, names);
  const nlohmann::json* after = nullptr;
  const nlohmann::json* table = nullptr;
  if (comesh) {
    ComeshOptions comeshOptions;
    comeshOptions.progress = [&](int outer, double energy) {
      char stage[96];
      std::snprintf(stage, sizeof stage, "comesh: outer iteration %d, energy %.6g", outer, energy);
      progress.update(stage, buildShare + (0.9 - buildShare) * outer / comeshOptions.outerIterations);
    };
    ComeshReport report;
    Multimesh optimized = comeshOptimize(*built.multimesh, &built.boundary, comeshOptions, &report);
    // Flips, splits and collapses made new triangles: paint them again from the scene.
    paintStiffness(optimized, scene.stiffness, scene.solver.kappa);
    try {
      optimized.validate();
    } catch (const InputError& e) {  // the input was fine: a broken result is our fault (exit 1)
      throw std::runtime_error(std::string("Comesh Optimization produced an invalid multimesh: ") + e.what());
    }
    progress.update("writing", 0.95);
    const fs::path initialFile = besideOutput(output, ".initial.ibmesh");
    saveMultimesh(*built.multimesh, initialFile.string());
    saveMultimesh(optimized, output.string());
    summary["initial"]["multimesh"] = initialFile.string();
    summary["comesh"] = comeshJson(report);
    summary["optimized"] = qualityJson(optimized, names);
    summary["optimized"]["multimesh"] = output.string();
    if (!options.flag("no-pictures")) {
      writePictures(scene, built, *built.multimesh, besideOutput(output, ".initial"), summary["initial"]);
      writePictures(scene, built, optimized, output, summary["optimized"]);
    }
    after = &summary["optimized"];
    table = &summary["comesh"];
  } else {
    progress.update("writing", 0.95);
    saveMultimesh(*built.multimesh, output.string());
    summary["initial"]["multimesh"] = output.string();
    if (!options.flag("no-pictures")) writePictures(scene, built, *built.multimesh, output, summary["initial"]);
  }
  progress.finish();
  if (options.flag("json")) {
    std::printf("%s\n", summary.dump().c_str());
    return 0;
  }
  const nlohmann::json& final = after ? *after : summary["initial"];
  std::printf("%s: %d vertices, %d triangles (edge length %.3g px)\n", scenePath.c_str(), final["vertices"].get<int>(),
              final["triangles"].get<int>(), built.edgeLength);
  printMeshReport(summary["initial"], after, table);
  if (after) std::printf("wrote %s (initial map: %s)\n", output.string().c_str(), summary["initial"]["multimesh"].get<std::string>().c_str());
  else std::printf("wrote %s\n", output.string().c_str());
  return 0;
}

}  // namespace ib
