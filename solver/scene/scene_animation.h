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

struct TimelineSettings;  // scene/scene.h

// The timeline of a scene's "timeline" object (null: absent) with its fps, loop and spacing read
// already (scene/parameters.h); keyNames in scene order. Without "marks": every key a second
// apart (defaultTimeline). Throws InputError naming the file and the field (its own fields other
// than "marks" are checked against the parameter table).
Timeline parseTimeline(const nlohmann::json* j, const std::vector<std::string>& keyNames, const TimelineSettings& settings,
                       const std::string& file);
// The same for a "timeline" object on its own: its fps, loop and spacing read from it.
Timeline parseTimeline(const nlohmann::json& j, const std::vector<std::string>& keyNames, const std::string& file);

// Reads "stiffness": range [soft, stiff], image {key, path} (path relative to `folder`), regions
// [{name, key, polygon, kappa}]. keyNames in scene order.
StiffnessPaint parseStiffness(const nlohmann::json& j, const json_fields::Context& at,
                              const std::vector<std::string>& keyNames, const std::string& folder);

}  // namespace ib
