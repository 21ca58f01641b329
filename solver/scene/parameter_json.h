// The parameter table (scene/parameters.h) in a scene file's JSON: reading every parameter into a
// Scene with the table's types and ranges (each error naming the file and field), and writing or
// removing one (the scene document's edits, the player's Save).
#pragma once

#include "core/json_fields.h"
#include "scene/parameters.h"

#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace ib {

struct Scene;

// The fields of `section` ("" for the top level, "solver", "tracing", "timeline", "dynamics")
// that hold parameters.
std::set<std::string> parameterFields(const std::string& section);

// Reads every parameter `root` holds (the scene file's object) into `scene` with the table's
// setters, checking each against the table: InputError naming the file and the field, e.g.
// `scene.json: dynamics: epsilon: 3 is out of range [0, 1]`. The sections' own fields are
// checked by the caller (requireObject).
void readParameters(const nlohmann::json& root, const json_fields::Context& at, Scene& scene);

// Sets the parameter's field in `root` to `value` (checked by the caller), creating its section
// when absent; a component of [x, y] keeps the other one (the default when the field is absent).
void writeParameter(nlohmann::ordered_json& root, const ParameterSpec& spec, double value);
// Removes the parameter's field, so the default holds (a component sets its coordinate to the
// default and removes the field when both are); an emptied section goes too.
void removeParameter(nlohmann::ordered_json& root, const ParameterSpec& spec);
// The value at the parameter's field in `root`, or the default when absent (root as written by
// writeParameter or a valid scene).
double parameterIn(const nlohmann::ordered_json& root, const ParameterSpec& spec);

}  // namespace ib
