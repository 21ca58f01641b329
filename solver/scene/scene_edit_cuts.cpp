// The scene document's edits of cuts (and the features they create), holes, and stiffness
// regions and strokes.
#include "scene/scene_edit_ops.h"

#include "core/error.h"
#include "scene/parameters.h"
#include "scene/scene.h"

#include <cmath>

namespace ib::edit {

namespace {

// Every cut name the scene draws, for "did you mean".
std::vector<std::string> cutNames(Json& root) {
  std::vector<std::string> names;
  for (const Json& k : keys(root))
    if (k.contains("cuts") && k["cuts"].is_array())
      for (const Json& c : k["cuts"])
        if (c.is_object() && c.contains("name") && c["name"].is_string()) names.push_back(c["name"].get<std::string>());
  return names;
}

// The cut `name` drawn in key `keyName`.
Json& cutIn(Json& root, const std::string& keyName, const std::string& name) {
  Json& k = key(root, keyName);
  if (k.contains("cuts") && k["cuts"].is_array()) {
    const int at = indexNamed(k["cuts"], name);
    if (at >= 0) return k["cuts"][static_cast<size_t>(at)];
  }
  notFound("cut in key " + q(keyName) + ", cut", name, cutNames(root));
}

Json& cutPoints(Json& cut) {
  if (!cut.contains("points") || !cut["points"].is_array()) cut["points"] = Json::array();
  return cut["points"];
}

void checkIndex(int index, size_t count, const std::string& what) {
  if (index < 0 || index >= static_cast<int>(count))
    throw InputError(what + ": point " + std::to_string(index + 1) + " is not one of 1.." + std::to_string(count));
}

// Features the cut `cut` creates ("cut.left", ...), whatever the kind: a name that starts "cut.".
bool createdBy(const std::string& feature, const std::string& cut) { return feature.rfind(cut + ".", 0) == 0; }

Json& holes(Json& root, const std::string& keyName) {
  Json& k = key(root, keyName);
  if (!k.contains("holes") || !k["holes"].is_array()) k["holes"] = Json::array();
  return k["holes"];
}

// The stiffness list ("regions" or "strokes"), created when absent.
Json& stiffnessList(Json& root, const char* list) {
  if (!root.contains("stiffness") || !root["stiffness"].is_object()) root["stiffness"] = Json::object();
  Json& stiffness = root["stiffness"];
  if (!stiffness.contains(list) || !stiffness[list].is_array()) stiffness[list] = Json::array();
  return stiffness[list];
}

// The region or stroke named `name`.
Json& painted(Json& root, const std::string& name) {
  std::vector<std::string> names;
  for (const char* list : {"regions", "strokes"}) {
    Json& items = stiffnessList(root, list);
    const int at = indexNamed(items, name);
    if (at >= 0) return items[static_cast<size_t>(at)];
    for (const Json& item : items) names.push_back(textOf(item, "name"));
  }
  notFound("stiffness region or stroke", name, names);
}

// Drops empty stiffness lists (and an emptied "stiffness") left by a lookup or a removal.
void tidyStiffness(Json& root) {
  if (!root.contains("stiffness") || !root["stiffness"].is_object()) return;
  Json& stiffness = root["stiffness"];
  for (const char* list : {"regions", "strokes"})
    if (stiffness.contains(list) && stiffness[list].is_array() && stiffness[list].empty()) stiffness.erase(list);
  if (stiffness.empty()) root.erase("stiffness");
}

void checkKappa(double kappa, const std::string& name) {
  checkParameterValue(parameter("kappa"), kappa, "stiffness " + q(name) + ": kappa");
}

void addPainted(Json& root, const char* list, Json item) {
  const std::string name = item["name"].get<std::string>();
  checkName(name, "stiffness region or stroke", false);
  if (indexNamed(stiffnessList(root, "regions"), name) >= 0 || indexNamed(stiffnessList(root, "strokes"), name) >= 0)
    throw InputError("stiffness " + q(name) + " exists already: choose another name");
  key(root, item["key"].get<std::string>());
  stiffnessList(root, list).push_back(std::move(item));
}

// kappa * factor as the file writes it, checked against the format's range; `where` names the field.
Json scaledKappa(const Json& kappa, double factor, const std::string& where) {
  if (!kappa.is_number()) throw InputError(where + ": must be a number to scale by " + std::to_string(factor));
  const double value = kappa.get<double>() * factor;
  const ParameterSpec& range = parameter("kappa");
  if (!parameterValueValid(range, value))
    throw InputError(where + ": scaling by " + std::to_string(factor) + " takes it out of " + formatParameterRange(range));
  return std::floor(value) == value && value < 1e15 ? Json(static_cast<long long>(value)) : Json(value);
}

void scaleStiffness(Json& root, double factor) {
  if (!(factor > 0 && std::isfinite(factor))) throw InputError("stiffness: a scale must be a number > 0");
  if (factor == 1) return;
  const Scene defaults;
  if (!root.contains("solver") || !root["solver"].is_object()) root["solver"] = Json::object();
  Json& solver = root["solver"];
  solver["kappa"] = scaledKappa(solver.contains("kappa") ? solver["kappa"] : Json(defaults.kappa), factor, "solver: kappa");
  if (!root.contains("stiffness") || !root["stiffness"].is_object()) return;
  Json& stiffness = root["stiffness"];
  if (stiffness.contains("range")) {
    Json& range = stiffness["range"];
    if (!range.is_array() || range.size() != 2) throw InputError("stiffness: range: must be [soft, stiff]");
    for (Json& end : range) end = scaledKappa(end, factor, "stiffness: range");
  } else if (stiffness.contains("image")) {
    const StiffnessPaint paint;
    stiffness["range"] = Json::array({scaledKappa(paint.soft, factor, "stiffness: range"),
                                      scaledKappa(paint.stiff, factor, "stiffness: range")});
  }
  for (const char* list : {"regions", "strokes"})
    if (stiffness.contains(list) && stiffness[list].is_array())
      for (Json& item : stiffness[list])
        if (item.is_object() && item.contains("kappa"))
          item["kappa"] = scaledKappa(item["kappa"], factor, std::string("stiffness: ") + list + ": " + q(textOf(item, "name")) + ": kappa");
}

}  // namespace

void applyCutEdit(Json& root, const SceneEdit& edit) {
  std::visit(
      Overloaded{
          [&](const AddCut& e) {
            checkName(e.name, "cut", true);
            if (e.kind != "notch" && e.kind != "split" && e.kind != "slit")
              throw InputError("cut " + q(e.name) + ": " + q(e.kind) + " is not a cut kind (notch, split or slit)");
            if (e.points.size() < 2) throw InputError("cut " + q(e.name) + " needs at least 2 points");
            Json& k = key(root, e.key);
            if (!k.contains("cuts") || !k["cuts"].is_array()) k["cuts"] = Json::array();
            if (indexNamed(k["cuts"], e.name) >= 0)
              throw InputError("key " + q(e.key) + " draws cut " + q(e.name) + " already: move its points instead");
            k["cuts"].push_back(Json{{"name", e.name}, {"kind", e.kind}, {"points", pointsJson(e.points)}});
          },
          [&](const SetCutRelease& e) {
            if (e.release && !(*e.release >= 0 && *e.release <= 1))
              throw InputError("cut " + q(e.cut) + ": release " + std::to_string(*e.release) + " is not in [0, 1]");
            int drawn = 0;
            for (Json& k : keys(root)) {
              if (!k.contains("cuts") || !k["cuts"].is_array()) continue;
              const int at = indexNamed(k["cuts"], e.cut);
              if (at < 0) continue;
              Json& cut = k["cuts"][static_cast<size_t>(at)];
              if (e.release) cut["release"] = std::round(*e.release * 1000) / 1000;
              else cut.erase("release");
              ++drawn;
            }
            if (drawn == 0) {
              std::vector<std::string> names;
              for (Json& k : keys(root))
                if (k.contains("cuts") && k["cuts"].is_array())
                  for (const Json& c : k["cuts"]) names.push_back(textOf(c, "name"));
              notFound("cut", e.cut, names);
            }
          },
          [&](const RemoveCut& e) {
            int removed = 0;
            for (Json& k : keys(root)) {
              if (!e.key.empty() && textOf(k, "name") != e.key) continue;
              if (k.contains("cuts") && k["cuts"].is_array()) {
                const int at = indexNamed(k["cuts"], e.name);
                if (at >= 0) k["cuts"].erase(static_cast<size_t>(at)), ++removed;
                if (k["cuts"].empty()) k.erase("cuts");
              }
              if (e.key.empty() && k.contains("features") && k["features"].is_object()) {
                Json kept = Json::object();
                for (auto it = k["features"].begin(); it != k["features"].end(); ++it)
                  if (!createdBy(it.key(), e.name)) kept[it.key()] = it.value();
                k["features"] = std::move(kept);
                if (k["features"].empty()) k.erase("features");
              }
            }
            if (removed == 0) notFound("cut", e.name, cutNames(root));
          },
          [&](const RenameCut& e) {
            checkName(e.to, "cut", true);
            int renamed = 0;
            for (const std::string& existing : cutNames(root))
              if (existing == e.to) throw InputError("cut " + q(e.to) + " exists already: choose another name");
            for (Json& k : keys(root)) {
              if (k.contains("cuts") && k["cuts"].is_array()) {
                const int at = indexNamed(k["cuts"], e.from);
                if (at >= 0) k["cuts"][static_cast<size_t>(at)]["name"] = e.to, ++renamed;
              }
              if (k.contains("features") && k["features"].is_object()) {
                Json kept = Json::object();
                for (auto it = k["features"].begin(); it != k["features"].end(); ++it)
                  kept[createdBy(it.key(), e.from) ? e.to + it.key().substr(e.from.size()) : it.key()] = it.value();
                k["features"] = std::move(kept);
              }
            }
            if (renamed == 0) notFound("cut", e.from, cutNames(root));
          },
          [&](const MoveCutPoint& e) {
            Json& points = cutPoints(cutIn(root, e.key, e.cut));
            checkIndex(e.index, points.size(), "cut " + q(e.cut));
            points[static_cast<size_t>(e.index)] = pointJson(e.at);
          },
          [&](const InsertCutPoint& e) {
            Json& points = cutPoints(cutIn(root, e.key, e.cut));
            if (e.index < 0 || e.index > static_cast<int>(points.size()))
              throw InputError("cut " + q(e.cut) + ": a point goes before points 1.." + std::to_string(points.size()) +
                               " or after the last (" + std::to_string(points.size()) + "), not at " + std::to_string(e.index));
            points.insert(points.begin() + e.index, pointJson(e.at));
          },
          [&](const RemoveCutPoint& e) {
            Json& points = cutPoints(cutIn(root, e.key, e.cut));
            checkIndex(e.index, points.size(), "cut " + q(e.cut));
            if (points.size() <= 2) throw InputError("cut " + q(e.cut) + " keeps at least 2 points: remove the cut instead");
            points.erase(static_cast<size_t>(e.index));
          },
          [&](const AddHole& e) { holes(root, e.key).push_back(pointJson(e.at)); },
          [&](const MoveHole& e) {
            Json& list = holes(root, e.key);
            checkIndex(e.index, list.size(), "holes of key " + q(e.key));
            list[static_cast<size_t>(e.index)] = pointJson(e.at);
          },
          [&](const RemoveHole& e) {
            Json& list = holes(root, e.key);
            checkIndex(e.index, list.size(), "holes of key " + q(e.key));
            list.erase(static_cast<size_t>(e.index));
            if (list.empty()) key(root, e.key).erase("holes");
          },
          [&](const AddStiffnessRegion& e) {
            if (e.polygon.size() < 3) throw InputError("stiffness region " + q(e.name) + " needs at least 3 points");
            checkKappa(e.kappa, e.name);
            addPainted(root, "regions",
                       Json{{"name", e.name}, {"key", e.key}, {"kappa", e.kappa}, {"polygon", pointsJson(e.polygon)}});
          },
          [&](const AddStiffnessStroke& e) {
            if (e.points.empty()) throw InputError("stiffness stroke " + q(e.name) + " needs at least 1 point");
            if (!(e.radius >= kMinStrokeRadius && e.radius <= kMaxStrokeRadius))
              throw InputError("stiffness stroke " + q(e.name) + ": radius " + shortestText(e.radius) + " px is out of range [" +
                               shortestText(kMinStrokeRadius) + ", " + shortestText(kMaxStrokeRadius) + "]");
            checkKappa(e.kappa, e.name);
            addPainted(root, "strokes",
                       Json{{"name", e.name}, {"key", e.key}, {"kappa", e.kappa}, {"radius", e.radius},
                            {"points", pointsJson(e.points)}});
          },
          [&](const RemoveStiffness& e) {
            painted(root, e.name);  // says what there is when the name is not
            for (const char* list : {"regions", "strokes"}) {
              Json& items = stiffnessList(root, list);
              const int at = indexNamed(items, e.name);
              if (at >= 0) items.erase(static_cast<size_t>(at));
            }
          },
          [&](const RenameStiffness& e) {
            checkName(e.to, "stiffness region or stroke", false);
            if (indexNamed(stiffnessList(root, "regions"), e.to) >= 0 || indexNamed(stiffnessList(root, "strokes"), e.to) >= 0)
              throw InputError("stiffness " + q(e.to) + " exists already: choose another name");
            painted(root, e.from)["name"] = e.to;
          },
          [&](const MoveStiffnessPoint& e) {
            Json& item = painted(root, e.name);
            Json& points = item.contains("polygon") ? item["polygon"] : item["points"];
            checkIndex(e.index, points.size(), "stiffness " + q(e.name));
            points[static_cast<size_t>(e.index)] = pointJson(e.at);
          },
          [&](const SetStiffnessKappa& e) {
            checkKappa(e.kappa, e.name);
            painted(root, e.name)["kappa"] = e.kappa;
          },
          [&](const ScaleStiffness& e) { scaleStiffness(root, e.factor); },
          [&](const auto&) { throw std::logic_error("applyCutEdit: not a cut, hole or stiffness edit"); }},
      edit);
  const bool stiffnessEdit = std::holds_alternative<AddStiffnessRegion>(edit) || std::holds_alternative<AddStiffnessStroke>(edit) ||
                             std::holds_alternative<RemoveStiffness>(edit) || std::holds_alternative<RenameStiffness>(edit) ||
                             std::holds_alternative<MoveStiffnessPoint>(edit) || std::holds_alternative<SetStiffnessKappa>(edit);
  if (stiffnessEdit) tidyStiffness(root);  // the lists the lookups made; other edits leave "stiffness" as the file has it
}

}  // namespace ib::edit
