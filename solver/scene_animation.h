// The animation parts of the scene file: "dynamics" and "stiffness" (README.md, "Scene file").
// The "timeline" object is read by parseTimeline (timeline.h).
#pragma once

#include "dynamics.h"
#include "json_fields.h"
#include "stiffness_paint.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ib {

// Reads "dynamics": epsilon, gravity, wind, gust, gust_frequency, mu, anchor, settle, max_deviation.
DynamicsParams parseDynamics(const nlohmann::json& j, const json_fields::Context& at);

// Reads "stiffness": range [soft, stiff], image {key, path} (path relative to `folder`), regions
// [{name, key, polygon, kappa}]. keyNames in scene order.
StiffnessPaint parseStiffness(const nlohmann::json& j, const json_fields::Context& at,
                              const std::vector<std::string>& keyNames, const std::string& folder);

}  // namespace ib
