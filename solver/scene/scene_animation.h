// The animation parts of the scene file: "timeline", "dynamics" and "stiffness"
// (docs/scene-format.md).
#pragma once

#include "animation/dynamics.h"
#include "animation/timeline.h"
#include "core/json_fields.h"
#include "scene/stiffness.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ib {

// Parses a scene's "timeline" object (docs/scene-format.md); keyNames in scene order. An absent
// "marks" gives the default timeline. Throws InputError naming the file (`file`) and the field.
Timeline parseTimeline(const nlohmann::json& j, const std::vector<std::string>& keyNames, const std::string& file);

// Reads "dynamics": epsilon, gravity, wind, gust, gust_frequency, mu, anchor, settle, max_deviation.
DynamicsParams parseDynamics(const nlohmann::json& j, const json_fields::Context& at);

// Reads "stiffness": range [soft, stiff], image {key, path} (path relative to `folder`), regions
// [{name, key, polygon, kappa}]. keyNames in scene order.
StiffnessPaint parseStiffness(const nlohmann::json& j, const json_fields::Context& at,
                              const std::vector<std::string>& keyNames, const std::string& folder);

}  // namespace ib
