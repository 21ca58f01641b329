#include "commands/mesh_command.h"

#include "cli.h"
#include "commands/mesh_report.h"
#include "commands/output_folder.h"
#include "comesh/comesh.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "meshing/matched_features.h"
#include "meshing/mesh_svg.h"
#include "multimesh/multimesh_io.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "scene/scene.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween mesh SCENE [-o OUT] [--json] [--no-pictures] [--no-comesh] [--suggest]\n"
    "\n"
    "Traces the scene's drawings, applies features and cuts, meshes the reference key, maps the\n"
    "mesh onto every key without foldovers, then improves every key's triangles and every map\n"
    "between keys together (Comesh Optimization). Prints the Comesh statistics and the quality\n"
    "before and after.\n"
    "\n"
    "  -o, --output OUT  multimesh file to write (default: SCENE's folder, SCENE's name .ibmesh);\n"
    "                    the initial map goes next to it as OUT's name .initial.ibmesh; OUT's\n"
    "                    folder is created if missing (and removed again if the command fails)\n"
    "  --json            print the summary as one JSON object\n"
    "  --no-pictures     skip the pictures, one SVG per key: OUT's name .KEY.svg, and for the\n"
    "                    initial map OUT's name .initial.KEY.svg (mesh over drawing, cohesive\n"
    "                    edges red, features and interior features as dots)\n"
    "  --no-comesh       write the initial map only, as OUT\n"
    "  --suggest         also list the outline's corners as the shape matching pairs them across\n"
    "                    the keys, with a confidence (0-1), as features to add to the scene\n";

namespace fs = std::filesystem;

fs::path besideOutput(const fs::path& output, const std::string& suffix) {
  return output.parent_path() / (output.stem().string() + suffix);
}

// One SVG per key of `mesh`, OUT's name + version + .KEY.svg; adds each picture's path to the
// key's entry in `quality`.
void writePictures(const Scene& scene, const SceneMultimesh& built, const Multimesh& mesh, const fs::path& output,
                   const std::string& version, nlohmann::json& quality) {
  for (size_t k = 0; k < scene.keys.size(); ++k) {
    const fs::path picture = besideOutput(output, version + "." + scene.keys[k].name + ".svg");
    const auto [width, height] = built.drawingSizes[k];
    std::vector<InteriorMark> interior;
    for (const auto& [name, at] : scene.keys[k].interiorFeatures) {
      const auto radius = scene.keys[k].interiorRadii.find(name);
      interior.push_back({name, at, radius == scene.keys[k].interiorRadii.end() ? 0.0 : radius->second});
    }
    writeFileAtomically(picture.string(), meshSvg(mesh, static_cast<int>(k), built.shapes[k],
                                                  readFile(scene.keys[k].drawing), width, height, interior));
    quality["keys"][k]["picture"] = picture.string();
  }
}

// Suggestions as JSON, named s1, s2, ... past the scene's feature names: [{"name", "confidence",
// "moved" (px), "at": {key: [x, y]}}].
nlohmann::json suggestionsJson(const Scene& scene, const std::vector<MatchedFeature>& suggestions) {
  nlohmann::json out = nlohmann::json::array();
  int next = 1;
  const auto taken = [&](const std::string& name) {
    for (const KeySpec& key : scene.keys)
      if (key.features.count(name) || key.interiorFeatures.count(name)) return true;
    return false;
  };
  for (const MatchedFeature& s : suggestions) {
    std::string name;
    do name = "s" + std::to_string(next++);
    while (taken(name));
    nlohmann::json at = nlohmann::json::object();
    for (size_t k = 0; k < scene.keys.size(); ++k)
      at[scene.keys[k].name] = {std::round(s.at[k].x() * 10) / 10, std::round(s.at[k].y() * 10) / 10};
    out.push_back({{"name", name}, {"confidence", std::round(s.confidence * 100) / 100},
                   {"moved", std::round(s.moved * 10) / 10}, {"at", at}});
  }
  return out;
}

void printSuggestions(const Scene& scene, const nlohmann::json& suggestions) {
  std::printf("suggested features: %zu (the outlines' corners as the shape matching pairs them across keys)\n",
              suggestions.size());
  for (const auto& s : suggestions) {
    std::printf("  %-4s confidence %.2f  moved %5.1f px ", s["name"].get<std::string>().c_str(), s["confidence"].get<double>(),
                s["moved"].get<double>());
    for (const KeySpec& key : scene.keys) {  // in the scene's order
      const nlohmann::json& at = s["at"][key.name];
      std::printf(" %s (%.1f, %.1f)", key.name.c_str(), at[0].get<double>(), at[1].get<double>());
    }
    std::printf("\n");
  }
  if (!suggestions.empty())
    std::printf("to keep one, add it to every key's \"features\" at that key's point (docs/scene-format.md)\n");
}

}  // namespace

int runMesh(const std::vector<std::string>& rawArgs) {
  const std::vector<std::string> args = cli::expandShortOutput(rawArgs);
  if (cli::printHelpIfAsked(args, kUsage)) return 0;
  const cli::Arguments options("mesh", args, {"output"}, {"json", "no-pictures", "no-comesh", "suggest"});
  if (options.positional().size() != 1) throw InputError("mesh: needs exactly one SCENE file (see `inbetween mesh --help`)");
  const std::string scenePath = options.positional()[0];
  const Scene scene = loadScene(scenePath);
  const fs::path output = options.value("output", cachedMeshPath(scenePath));
  const bool pictures = !options.flag("no-pictures");
  // OUT's folder, created before the long work and removed again if the command fails.
  std::optional<cli::OutputFolder> folder;
  if (!output.parent_path().empty()) folder.emplace(output.parent_path().string(), "-o");
  std::vector<std::string> names;
  for (const KeySpec& key : scene.keys) names.push_back(key.name);

  cli::Progress progress;
  SceneMultimeshOptions meshOptions;
  meshOptions.useCache = false;  // this command makes the cache
  meshOptions.comesh = !options.flag("no-comesh");
  const SceneMultimesh built =
      sceneMultimesh(scene, meshOptions, [&](const std::string& stage, double fraction) { progress.update(stage, 0.9 * fraction); });
  nlohmann::json summary{{"scene", scenePath}, {"edge_length", built.edgeLength}};
  summary["initial"] = qualityJson(*built.initial, names, &built.shapes);
  const nlohmann::json* after = nullptr;
  const nlohmann::json* table = nullptr;
  progress.update("writing", 0.95);
  if (built.comesh) {
    const fs::path initialFile = besideOutput(output, ".initial.ibmesh");
    saveMultimesh(*built.initial, initialFile.string());
    saveMultimesh(*built.multimesh, output.string());
    summary["initial"]["multimesh"] = initialFile.string();
    summary["comesh"] = comeshJson(*built.comesh);
    summary["optimized"] = qualityJson(*built.multimesh, names, &built.shapes);
    summary["optimized"]["multimesh"] = output.string();
    if (pictures) {
      writePictures(scene, built, *built.initial, output, ".initial", summary["initial"]);
      writePictures(scene, built, *built.multimesh, output, "", summary["optimized"]);
    }
    after = &summary["optimized"];
    table = &summary["comesh"];
  } else {
    saveMultimesh(*built.initial, output.string());
    summary["initial"]["multimesh"] = output.string();
    if (pictures) writePictures(scene, built, *built.initial, output, "", summary["initial"]);
  }
  if (options.flag("suggest")) summary["suggestions"] = suggestionsJson(scene, matchedFeatures(scene, built.shapes));
  progress.finish();
  if (folder) folder->keep();
  for (const std::string& note : built.notes) std::fprintf(stderr, "inbetween: note: %s\n", note.c_str());
  if (options.flag("json")) {
    std::printf("%s\n", summary.dump().c_str());
    return 0;
  }
  const nlohmann::json& final = after ? *after : summary["initial"];
  std::printf("%s: %d vertices, %d triangles (edge length %.3g px)\n", scenePath.c_str(), final["vertices"].get<int>(),
              final["triangles"].get<int>(), built.edgeLength);
  printMeshReport(summary["initial"], after, table);
  if (summary.contains("suggestions")) printSuggestions(scene, summary["suggestions"]);
  if (after) std::printf("wrote %s (initial map: %s)\n", output.string().c_str(), summary["initial"]["multimesh"].get<std::string>().c_str());
  else std::printf("wrote %s\n", output.string().c_str());
  return 0;
}

}  // namespace ib
