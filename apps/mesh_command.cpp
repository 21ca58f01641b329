#include "mesh_command.h"

#include "atomic_file.h"
#include "cli.h"
#include "error.h"
#include "mesh_quality.h"
#include "mesh_svg.h"
#include "multimesh_builder.h"
#include "multimesh_io.h"
#include "progress.h"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween mesh SCENE [-o OUT] [--json] [--no-pictures]\n"
    "\n"
    "Traces the scene's drawings, applies features and cuts, meshes the reference key and maps\n"
    "the mesh onto every key without foldovers.\n"
    "\n"
    "  -o, --output OUT  multimesh file to write (default: SCENE's folder, SCENE's name .ibmesh)\n"
    "  --json            print the summary as one JSON object\n"
    "  --no-pictures     skip the pictures (OUT's name, then .KEY.svg: mesh over drawing,\n"
    "                    cohesive edges red, features as dots)\n";

namespace fs = std::filesystem;

}  // namespace

int runMesh(const std::vector<std::string>& rawArgs) {
  std::vector<std::string> args;
  for (const std::string& a : rawArgs) args.push_back(a == "-o" ? "--output" : a);
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
  const cli::Arguments options("mesh", args, {"output"}, {"json", "no-pictures"});
  if (options.positional().size() != 1) throw InputError("mesh: needs exactly one SCENE file (see `inbetween mesh --help`)");
  const std::string scenePath = options.positional()[0];
  const Scene scene = loadScene(scenePath);
  const fs::path output = options.value("output", (fs::path(scenePath).parent_path() / fs::path(scenePath).stem()).string() + ".ibmesh");

  cli::Progress progress;
  MultimeshBuildOptions buildOptions;
  buildOptions.progress = [&](const std::string& stage, double fraction) { progress.update(stage, 0.9 * fraction); };
  const BuiltScene built = buildMultimesh(scene, buildOptions);
  progress.update("writing", 0.95);
  saveMultimesh(*built.multimesh, output.string());

  nlohmann::json summary;
  summary["scene"] = scenePath;
  summary["multimesh"] = output.string();
  summary["vertices"] = built.multimesh->vertexCount();
  summary["triangles"] = built.multimesh->triangleCount();
  summary["edge_length"] = built.edgeLength;
  summary["keys"] = nlohmann::json::array();
  const MultimeshQuality quality = measureQuality(*built.multimesh);
  for (size_t k = 0; k < built.report.size(); ++k) {
    nlohmann::json key{{"name", built.report[k].key},
                       {"cohesive_edges", built.report[k].cohesiveEdges},
                       {"smallest_area", built.report[k].smallestArea},
                       {"smallest_angle", quality.keys[k].smallestAngle},
                       {"mean_smallest_angle", quality.keys[k].meanSmallestAngle},
                       {"share_under_20_degrees", quality.keys[k].shareUnder20}};
    if (!options.flag("no-pictures")) {
      const fs::path picture = output.parent_path() / (output.stem().string() + "." + built.report[k].key + ".svg");
      const auto [width, height] = built.drawingSizes[k];
      writeFileAtomically(picture.string(), meshSvg(*built.multimesh, static_cast<int>(k), built.shapes[k],
                                                    readFile(scene.keys[k].drawing), width, height));
      key["picture"] = picture.string();
    }
    summary["keys"].push_back(key);
  }
  summary["maps"] = nlohmann::json::array();
  for (const MapQuality& map : quality.maps)
    summary["maps"].push_back({{"from", built.report[map.from].key}, {"to", built.report[map.to].key},
                               {"mips_mean", map.mipsMean}, {"mips_max", map.mipsMax}});
  progress.finish();
  if (options.flag("json")) {
    std::printf("%s\n", summary.dump().c_str());
    return 0;
  }
  std::printf("%s: %d vertices, %d triangles (edge length %.3g px)\n", scenePath.c_str(), built.multimesh->vertexCount(),
              built.multimesh->triangleCount(), built.edgeLength);
  for (const auto& key : summary["keys"])
    std::printf("  key %-12s %5d cohesive edges, smallest triangle %.3g px^2, angles >= %.1f deg (mean smallest "
                "%.1f, %.1f%% under 20)%s%s\n",
                ("\"" + key["name"].get<std::string>() + "\"").c_str(), key["cohesive_edges"].get<int>(),
                key["smallest_area"].get<double>(), key["smallest_angle"].get<double>(),
                key["mean_smallest_angle"].get<double>(), 100 * key["share_under_20_degrees"].get<double>(),
                key.contains("picture") ? ", picture " : "",
                key.contains("picture") ? key["picture"].get<std::string>().c_str() : "");
  for (const auto& map : summary["maps"])
    std::printf("  map %s -> %s: MIPS mean %.3f, max %.3g (2 is conformal)\n", map["from"].get<std::string>().c_str(),
                map["to"].get<std::string>().c_str(), map["mips_mean"].get<double>(), map["mips_max"].get<double>());
  std::printf("wrote %s\n", output.string().c_str());
  return 0;
}

}  // namespace ib
