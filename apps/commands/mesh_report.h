// What `inbetween mesh` reports: the multimesh's quality (per key and per cyclic key pair, before
// and after Comesh Optimization) and the Comesh row of the paper's Table 2, as JSON and as text.
#pragma once

#include "comesh/comesh.h"
#include "meshing/key_shape.h"
#include "multimesh/multimesh.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ib {

// {"vertices", "triangles", "keys": [{name, cohesive_edges, smallest_area, smallest_angle,
// mean_smallest_angle, share_under_20_degrees, outline_deviation, outline_deviation_at}], "maps": [{from, to, mips_mean,
// mips_max}]}. outline_deviation (px, meshing/outline_fit.h) and where ([x, y] px) only when `shapes` (one per key) is
// given and not empty.
nlohmann::json qualityJson(const Multimesh& mesh, const std::vector<std::string>& keyNames,
                           const std::vector<KeyShape>* shapes = nullptr);

// The Table 2 columns: keys, vertices/triangles/cohesive edges in and out, inner and outer
// iterations, seconds in flips, collapses, splits and in total; plus operation counts and energies.
nlohmann::json comeshJson(const ComeshReport& report);

// Human-readable: the Table 2 row, then per key and per map the figures before -> after
// (`after` may be null: only the initial figures).
void printMeshReport(const nlohmann::json& before, const nlohmann::json* after, const nlohmann::json* comesh);

}  // namespace ib
