#include "commands/mesh_report.h"

#include "meshing/outline_fit.h"
#include "meshing/untangle.h"
#include "multimesh/mesh_quality.h"

#include <Eigen/Dense>

#include <cstdio>

namespace ib {

nlohmann::json qualityJson(const Multimesh& mesh, const std::vector<std::string>& keyNames,
                           const std::vector<KeyShape>* shapes) {
  const MultimeshQuality quality = measureQuality(mesh);
  const std::vector<OutlineFit> fits = shapes && !shapes->empty() ? outlineFits(mesh, *shapes) : std::vector<OutlineFit>{};
  nlohmann::json out{{"vertices", mesh.vertexCount()}, {"triangles", mesh.triangleCount()}};
  out["keys"] = nlohmann::json::array();
  const std::vector<Triangle> triangles = mesh.triangles();
  for (int k = 0; k < mesh.keyCount(); ++k) {
    const double smallestArea = smallestTriangleArea(triangles, mesh.keyPositions(k)).first;
    out["keys"].push_back({{"name", keyNames[k]},
                           {"cohesive_edges", mesh.cohesivePairs(k).size()},
                           {"smallest_area", smallestArea},
                           {"smallest_angle", quality.keys[k].smallestAngle},
                           {"mean_smallest_angle", quality.keys[k].meanSmallestAngle},
                           {"share_under_20_degrees", quality.keys[k].shareUnder20}});
    if (!fits.empty()) {
      out["keys"].back()["outline_deviation"] = fits[k].largest;
      out["keys"].back()["outline_deviation_at"] = {fits[k].where.x(), fits[k].where.y()};
    }
  }
  out["maps"] = nlohmann::json::array();
  for (const MapQuality& map : quality.maps)
    out["maps"].push_back({{"from", keyNames[map.from]}, {"to", keyNames[map.to]},
                           {"mips_mean", map.mipsMean}, {"mips_max", map.mipsMax}});
  return out;
}

nlohmann::json comeshJson(const ComeshReport& r) {
  return {{"keys", r.keys},
          {"vertices_in", r.verticesIn}, {"vertices_out", r.verticesOut},
          {"triangles_in", r.trianglesIn}, {"triangles_out", r.trianglesOut},
          {"cohesive_in", r.cohesiveIn}, {"cohesive_out", r.cohesiveOut},
          {"inner", r.innerIterations}, {"outer", r.outerIterations},
          {"flips", r.remesh.flips}, {"splits", r.remesh.splits}, {"collapses", r.remesh.collapses},
          {"flip_seconds", r.remesh.flipSeconds}, {"collapse_seconds", r.remesh.collapseSeconds},
          {"split_seconds", r.remesh.splitSeconds}, {"seconds", r.seconds},
          {"energy_in", r.energyIn}, {"energy_out", r.energyOut}};
}

namespace {

// "a -> b" for a figure before and (when there is an after) after.
std::string change(const nlohmann::json& before, const nlohmann::json* after, const char* field, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, before[field].get<double>());
  std::string out = text;
  if (after) {
    std::snprintf(text, sizeof text, format, (*after)[field].get<double>());
    out += std::string(" -> ") + text;
  }
  return out;
}

}  // namespace

void printMeshReport(const nlohmann::json& before, const nlohmann::json* after, const nlohmann::json* comesh) {
  if (comesh) {
    const nlohmann::json& c = *comesh;
    std::printf("comesh: %d keys, vertices %d/%d, triangles %d/%d, cohesive edges %d/%d, inner %d, outer %d, "
                "flips %.3f s, collapses %.3f s, splits %.3f s, total %.3f s (%d flips, %d splits, %d collapses)\n",
                c["keys"].get<int>(), c["vertices_in"].get<int>(), c["vertices_out"].get<int>(),
                c["triangles_in"].get<int>(), c["triangles_out"].get<int>(), c["cohesive_in"].get<int>(),
                c["cohesive_out"].get<int>(), c["inner"].get<int>(), c["outer"].get<int>(),
                c["flip_seconds"].get<double>(), c["collapse_seconds"].get<double>(), c["split_seconds"].get<double>(),
                c["seconds"].get<double>(), c["flips"].get<int>(), c["splits"].get<int>(), c["collapses"].get<int>());
  }
  std::printf("quality%s:\n", after ? " (initial -> optimized)" : " (initial map)");
  for (size_t k = 0; k < before["keys"].size(); ++k) {
    const nlohmann::json& key = before["keys"][k];
    const nlohmann::json* next = after ? &(*after)["keys"][k] : nullptr;
    std::printf("  key %-12s smallest angle %s deg, mean smallest %s deg, share under 20 deg %s",
                ("\"" + key["name"].get<std::string>() + "\"").c_str(), change(key, next, "smallest_angle", "%.1f").c_str(),
                change(key, next, "mean_smallest_angle", "%.1f").c_str(),
                change(key, next, "share_under_20_degrees", "%.3f").c_str());
    if (key.contains("outline_deviation") && (!next || next->contains("outline_deviation")))
      std::printf(", outline to mesh boundary %s px", change(key, next, "outline_deviation", "%.2f").c_str());
    std::printf("\n");
  }
  for (size_t i = 0; i < before["maps"].size(); ++i) {
    const nlohmann::json& map = before["maps"][i];
    const nlohmann::json* next = after ? &(*after)["maps"][i] : nullptr;
    std::printf("  map %s -> %s: MIPS mean %s, max %s (2 is conformal)\n", map["from"].get<std::string>().c_str(),
                map["to"].get<std::string>().c_str(), change(map, next, "mips_mean", "%.3f").c_str(),
                change(map, next, "mips_max", "%.3g").c_str());
  }
}

}  // namespace ib
