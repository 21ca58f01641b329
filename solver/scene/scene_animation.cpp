#include "scene/scene_animation.h"

#include <algorithm>
#include <filesystem>

namespace ib {

using nlohmann::json;
using namespace json_fields;

namespace {

int keyNamed(const json& j, const std::vector<std::string>& keyNames, const Context& at) {
  const std::string name = text(j, "key", at);
  const auto found = std::find(keyNames.begin(), keyNames.end(), name);
  if (found == keyNames.end()) throw at.in("key").error(inQuotes(name) + " is not a key of this scene");
  return static_cast<int>(found - keyNames.begin());
}

StiffnessRegion parseRegion(const json& j, const Context& first, const std::vector<std::string>& keyNames) {
  requireObject(j, first, {"name", "key", "polygon", "kappa"});
  StiffnessRegion region;
  region.name = text(j, "name", first);
  const Context& at = first;  // `region "NAME"` (json_fields::element)
  region.key = keyNamed(j, keyNames, at);
  if (!j.contains("polygon") || !j["polygon"].is_array() || j["polygon"].size() < 3)
    throw at.error("needs \"polygon\": at least 3 points [x, y] in the key's drawing pixels");
  for (size_t i = 0; i < j["polygon"].size(); ++i)
    region.polygon.push_back(point(j["polygon"][i], at.in("polygon point " + std::to_string(i + 1))));
  if (!j.contains("kappa")) throw at.error("missing field \"kappa\"");
  region.kappa = number(j, "kappa", 1, at, 0, 1e6, true);
  return region;
}

}  // namespace

DynamicsParams parseDynamics(const json& j, const Context& at) {
  requireObject(j, at,
                {"epsilon", "gravity", "wind", "gust", "gust_frequency", "mu", "anchor", "settle", "max_deviation"});
  DynamicsParams d;
  d.epsilon = number(j, "epsilon", d.epsilon, at, 0, 1);
  const std::string vector = "in shape sizes per second squared (y down)";
  if (j.contains("gravity")) d.gravity = point(j["gravity"], at.in("gravity"), vector);
  if (j.contains("wind")) d.wind = point(j["wind"], at.in("wind"), vector);
  d.gust = number(j, "gust", d.gust, at, 0, 1);
  d.gustFrequency = number(j, "gust_frequency", d.gustFrequency, at, 0, 1000, true);
  d.mu = number(j, "mu", d.mu, at, 0, 1e6);
  d.anchor = number(j, "anchor", d.anchor, at, 0, 1e6, true);
  d.settle = number(j, "settle", d.settle, at, 0, 1, true);
  d.maxDeviation = number(j, "max_deviation", d.maxDeviation, at, 0, 100, true);
  return d;
}

StiffnessPaint parseStiffness(const json& j, const Context& at, const std::vector<std::string>& keyNames,
                              const std::string& folder) {
  requireObject(j, at, {"range", "image", "regions"});
  StiffnessPaint paint;
  if (j.contains("range")) {
    const Eigen::Vector2d range = point(j["range"], at.in("range"), "as [soft, stiff] kappa");
    if (!(range(0) > 0 && range(1) > range(0) && range(1) <= 1e6))
      throw at.in("range").error("needs 0 < soft < stiff <= 1e6");
    paint.soft = range(0);
    paint.stiff = range(1);
  }
  if (j.contains("image")) {
    const Context image = at.in("image");
    requireObject(j["image"], image, {"key", "path"});
    paint.imageKey = keyNamed(j["image"], keyNames, image);
    const std::filesystem::path path = text(j["image"], "path", image);
    paint.image = (path.is_absolute() ? path : std::filesystem::path(folder) / path).lexically_normal().string();
  }
  if (j.contains("regions")) {
    if (!j["regions"].is_array()) throw at.in("regions").error("must be an array of regions");
    for (size_t r = 0; r < j["regions"].size(); ++r)
      paint.regions.push_back(parseRegion(j["regions"][r], element(j["regions"][r], at, "region", r), keyNames));
  }
  return paint;
}

}  // namespace ib
