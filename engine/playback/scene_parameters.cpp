#include "playback/scene_parameters.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "playback/live_parameters.h"
#include "scene/scene.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace ib::play {

namespace {

using Json = nlohmann::ordered_json;

// The format's largest kappa (solver.kappa, stiffness.range, regions[].kappa).
constexpr double kMaxKappa = 1e6;

// A whole number is written as one (24, not 24.0), so untouched integers read as they did.
Json numberJson(double value) {
  if (std::floor(value) == value && std::fabs(value) < 1e15) return Json(static_cast<long long>(value));
  return Json(value);
}

// Sets section.field to value when the file has the field or the value differs from the format's
// default (then the section is created when absent).
void saveField(Json& root, const char* section, const char* field, const Json& value, const Json& byDefault) {
  const bool present = root.contains(section) && root[section].is_object() && root[section].contains(field);
  if (!present && value == byDefault) return;
  if (!root.contains(section) || !root[section].is_object()) root[section] = Json::object();
  root[section][field] = value;
}

void saveNumber(Json& root, const char* section, const char* field, double value, double byDefault) {
  saveField(root, section, field, numberJson(value), numberJson(byDefault));
}

void savePoint(Json& root, const char* section, const char* field, const Eigen::Vector2d& value) {
  saveField(root, section, field, Json::array({numberJson(value.x()), numberJson(value.y())}),
            Json::array({0, 0}));
}

// kappa * scale, checked against the format's range; `where` names the field.
Json scaledKappa(const Json& kappa, double scale, const std::string& where) {
  if (!kappa.is_number()) throw InputError(where + ": must be a number to scale by kappa_scale");
  const double value = kappa.get<double>() * scale;
  if (!(value > 0 && value <= kMaxKappa))
    throw InputError(where + ": kappa_scale " + std::to_string(scale) + " takes it out of (0, 1e6]");
  return numberJson(value);
}

// Bakes kappa_scale into every stiffness the scene names (see scene_parameters.h).
void saveKappaScale(Json& root, double scale, const std::string& file) {
  if (scale == 1) return;
  const SceneSolverParams defaults;
  const Json kappa = root.contains("solver") && root["solver"].is_object() && root["solver"].contains("kappa")
                         ? root["solver"]["kappa"]
                         : numberJson(defaults.kappa);
  saveField(root, "solver", "kappa", scaledKappa(kappa, scale, file + ": solver: kappa"), numberJson(defaults.kappa));
  if (!root.contains("stiffness") || !root["stiffness"].is_object()) return;
  Json& stiffness = root["stiffness"];
  const std::string at = file + ": stiffness: ";
  if (stiffness.contains("range")) {
    Json& range = stiffness["range"];
    if (!range.is_array() || range.size() != 2) throw InputError(at + "range: must be [soft, stiff]");
    for (Json& end : range) end = scaledKappa(end, scale, at + "range");
  } else if (stiffness.contains("image")) {
    const StiffnessPaint defaults;
    stiffness["range"] = Json::array({scaledKappa(numberJson(defaults.soft), scale, at + "range"),
                                      scaledKappa(numberJson(defaults.stiff), scale, at + "range")});
  }
  if (stiffness.contains("regions") && stiffness["regions"].is_array()) {
    for (Json& region : stiffness["regions"]) {
      if (!region.is_object() || !region.contains("kappa")) continue;
      const std::string name = region.contains("name") && region["name"].is_string() ? region["name"].get<std::string>() : "";
      region["kappa"] = scaledKappa(region["kappa"], scale, at + "region " + inQuotes(name) + ": kappa");
    }
  }
}

}  // namespace

void saveParameters(const std::string& scenePath, const LiveParameters& params, double fps) {
  if (!(fps > 0 && fps <= 1000)) throw InputError(scenePath + ": timeline: fps " + std::to_string(fps) + " is not in (0, 1000]");
  Json root = Json::parse(readFile(scenePath), nullptr, false);
  if (root.is_discarded() || !root.is_object())
    throw InputError(scenePath + ": cannot save parameters: not a JSON object (fix the file first)");

  const SceneSolverParams solver;
  const InterpolationParams tuned = params.interpolation();
  saveNumber(root, "solver", "tau", tuned.cohesive.tau, solver.tau);
  saveNumber(root, "solver", "alpha", tuned.cohesive.alpha, solver.alpha);
  saveNumber(root, "solver", "lambda", tuned.cohesive.lambda, solver.lambda);
  saveField(root, "solver", "non_overlap", Json(tuned.nonOverlap), Json(solver.nonOverlap));
  saveKappaScale(root, params.kappaScale(), scenePath);

  const DynamicsParams dynamics;
  const DynamicsParams d = params.dynamics();
  saveNumber(root, "dynamics", "epsilon", d.epsilon, dynamics.epsilon);
  saveNumber(root, "dynamics", "mu", d.mu, dynamics.mu);
  savePoint(root, "dynamics", "gravity", d.gravity);
  savePoint(root, "dynamics", "wind", d.wind);
  saveNumber(root, "dynamics", "anchor", d.anchor, dynamics.anchor);

  const Timeline plain = defaultTimeline({"key"});
  saveNumber(root, "timeline", "fps", fps, plain.fps());

  writeFileAtomically(scenePath, root.dump(2) + "\n");
}

}  // namespace ib::play
