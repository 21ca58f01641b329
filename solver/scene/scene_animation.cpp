#include "scene/scene_animation.h"

#include "core/suggest.h"
#include "scene/parameters.h"

#include <algorithm>
#include <filesystem>
#include <set>

namespace ib {

using nlohmann::json;
using namespace json_fields;

namespace {

int keyNamed(const json& j, const std::vector<std::string>& keyNames, const Context& at) {
  const std::string name = text(j, "key", at);
  const auto found = std::find(keyNames.begin(), keyNames.end(), name);
  if (found == keyNames.end())
    throw at.in("key").error(inQuotes(name) + " is not a key of this scene" + didYouMean(name, keyNames));
  return static_cast<int>(found - keyNames.begin());
}

// A painted kappa: a number in solver.kappa's range (the parameter table's "kappa").
double kappaOf(const json& j, const Context& at) {
  const ParameterSpec& kappa = parameter("kappa");
  return number(j, "kappa", kappa.defaultValue, at, kappa.min, kappa.max, kappa.minOpen);
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
  region.kappa = kappaOf(j, at);
  return region;
}

StiffnessStroke parseStroke(const json& j, const Context& at, const std::vector<std::string>& keyNames) {
  requireObject(j, at, {"name", "key", "points", "radius", "kappa"});
  StiffnessStroke stroke;
  stroke.name = text(j, "name", at);
  stroke.key = keyNamed(j, keyNames, at);
  if (!j.contains("points") || !j["points"].is_array() || j["points"].empty())
    throw at.error("needs \"points\": at least 1 point [x, y] in the key's drawing pixels");
  for (size_t i = 0; i < j["points"].size(); ++i)
    stroke.points.push_back(point(j["points"][i], at.in("point " + std::to_string(i + 1))));
  if (!j.contains("radius")) throw at.error("missing field \"radius\" (px)");
  stroke.radius = number(j, "radius", 4, at, kMinStrokeRadius, kMaxStrokeRadius);
  if (!j.contains("kappa")) throw at.error("missing field \"kappa\"");
  stroke.kappa = kappaOf(j, at);
  return stroke;
}

}  // namespace

StiffnessPaint parseStiffness(const json& j, const Context& at, const std::vector<std::string>& keyNames,
                              const std::string& folder) {
  requireObject(j, at, {"range", "image", "regions", "strokes"});
  StiffnessPaint paint;
  if (j.contains("range")) {
    const Eigen::Vector2d range = point(j["range"], at.in("range"), "as [soft, stiff] kappa");
    const ParameterSpec& kappa = parameter("kappa");
    if (!(parameterValueValid(kappa, range(0)) && parameterValueValid(kappa, range(1)) && range(1) > range(0)))
      throw at.in("range").error("needs 0 < soft < stiff <= 1e6, each in kappa's range " + formatParameterRange(kappa));
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
  if (j.contains("strokes")) {
    if (!j["strokes"].is_array()) throw at.in("strokes").error("must be an array of strokes");
    for (size_t s = 0; s < j["strokes"].size(); ++s)
      paint.strokes.push_back(parseStroke(j["strokes"][s], element(j["strokes"][s], at, "stroke", s), keyNames));
  }
  std::set<std::string> names;  // regions and strokes are named apart, for the editor to tell them apart
  for (const StiffnessRegion& region : paint.regions)
    if (!names.insert(region.name).second) throw at.error("region " + inQuotes(region.name) + " is named twice");
  for (const StiffnessStroke& stroke : paint.strokes)
    if (!names.insert(stroke.name).second)
      throw at.error("stroke " + inQuotes(stroke.name) + " has the name of another region or stroke");
  return paint;
}

}  // namespace ib
