// The scene document's edits: the dispatcher, the shared helpers, describe(), and the edits of
// keys, features and interior features.
#include "scene/scene_edit_ops.h"

#include "core/error.h"
#include "core/suggest.h"
#include "scene/parameters.h"
#include "scene/scene.h"

#include <cmath>
#include <sstream>

namespace ib::edit {

namespace {

// The object of `holder[field]` ("features", "interior_features"), created when absent.
Json& objectField(Json& holder, const std::string& field) {
  if (!holder.contains(field) || !holder[field].is_object()) holder[field] = Json::object();
  return holder[field];
}

// Renames member `from` of `object` to `to` in place, keeping the members' order.
void renameMember(Json& object, const std::string& from, const std::string& to) {
  Json renamed = Json::object();
  for (auto it = object.begin(); it != object.end(); ++it) renamed[it.key() == from ? to : it.key()] = it.value();
  object = std::move(renamed);
}

// Every place the scene names key `from` (reference, marks, stiffness) now names `to`; with `to`
// empty, those places go (a removed key).
void renameKeyUses(Json& root, const std::string& from, const std::string& to) {
  if (root.contains("reference") && root["reference"] == from) {
    if (to.empty()) root.erase("reference");
    else root["reference"] = to;
  }
  if (root.contains("timeline") && root["timeline"].contains("marks") && root["timeline"]["marks"].is_array()) {
    Json& marks = root["timeline"]["marks"];
    for (size_t m = marks.size(); m-- > 0;) {
      Json& mark = marks[m];
      if (mark.contains("key") && mark["key"] == from) {
        if (to.empty()) marks.erase(m);
        else mark["key"] = to;
      } else if (mark.contains("weights") && mark["weights"].is_object() && mark["weights"].contains(from)) {
        if (to.empty()) mark["weights"].erase(from);
        else renameMember(mark["weights"], from, to);
        if (mark["weights"].empty()) marks.erase(m);
      }
    }
  }
  if (!root.contains("stiffness") || !root["stiffness"].is_object()) return;
  Json& stiffness = root["stiffness"];
  if (stiffness.contains("image") && stiffness["image"].is_object() && textOf(stiffness["image"], "key") == from) {
    if (to.empty()) stiffness.erase("image");
    else stiffness["image"]["key"] = to;
  }
  for (const char* list : {"regions", "strokes"}) {
    if (!stiffness.contains(list) || !stiffness[list].is_array()) continue;
    Json& items = stiffness[list];
    for (size_t i = items.size(); i-- > 0;)
      if (items[i].is_object() && textOf(items[i], "key") == from) {
        if (to.empty()) items.erase(i);
        else items[i]["key"] = to;
      }
  }
}

// Features (field "features" or "interior_features") named `name` in key `keyName`, or in every
// key when empty: removed; InputError when none has it.
void removeNamed(Json& root, const std::string& field, const std::string& what, const std::string& name,
                 const std::string& keyName) {
  int removed = 0;
  std::vector<std::string> known;
  for (Json& k : keys(root)) {
    if (!keyName.empty() && textOf(k, "name") != keyName) continue;
    if (!k.contains(field) || !k[field].is_object()) continue;
    for (auto it = k[field].begin(); it != k[field].end(); ++it) known.push_back(it.key());
    removed += static_cast<int>(k[field].erase(name));
    if (k[field].empty()) k.erase(field);
  }
  if (!keyName.empty()) key(root, keyName);  // a key that does not exist: its own message
  if (removed == 0) notFound(what, name, known);
}

void renameNamed(Json& root, const std::string& field, const std::string& what, const std::string& from,
                 const std::string& to) {
  int renamed = 0;
  std::vector<std::string> known;
  for (Json& k : keys(root)) {
    if (!k.contains(field) || !k[field].is_object()) continue;
    Json& object = k[field];
    for (auto it = object.begin(); it != object.end(); ++it) known.push_back(it.key());
    if (!object.contains(from)) continue;
    if (object.contains(to))
      throw InputError("key " + q(textOf(k, "name")) + " already has " + what + " " + q(to) + ": choose another name");
    renameMember(object, from, to);
    ++renamed;
  }
  if (renamed == 0) notFound(what, from, known);
}

}  // namespace

std::string textOf(const Json& j, const char* field) {
  if (!j.is_object() || !j.contains(field) || !j[field].is_string()) return "";
  return j[field].get<std::string>();
}

bool flagOf(const Json& j, const char* field, bool fallback) {
  if (!j.is_object() || !j.contains(field) || !j[field].is_boolean()) return fallback;
  return j[field].get<bool>();
}

Json& keys(Json& root) {
  if (!root.contains("keys") || !root["keys"].is_array()) root["keys"] = Json::array();
  return root["keys"];
}

std::vector<std::string> keyNames(const Json& root) {
  std::vector<std::string> names;
  if (root.contains("keys") && root["keys"].is_array())
    for (const Json& k : root["keys"])
      if (k.is_object() && k.contains("name") && k["name"].is_string()) names.push_back(k["name"].get<std::string>());
  return names;
}

Json& key(Json& root, const std::string& name) {
  for (Json& k : keys(root))
    if (k.is_object() && textOf(k, "name") == name) return k;
  notFound("key", name, keyNames(root));
}

Json pointJson(const Point& p) {
  const auto coordinate = [](double v) {
    const double rounded = std::round(v * 1000) / 1000;
    return rounded == std::floor(rounded) && std::fabs(rounded) < 1e15 ? Json(static_cast<long long>(rounded)) : Json(rounded);
  };
  if (!p.allFinite()) throw InputError("a point must be finite, got (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")");
  return Json::array({coordinate(p.x()), coordinate(p.y())});
}

Json pointsJson(const Points& points) {
  Json out = Json::array();
  for (const Point& p : points) out.push_back(pointJson(p));
  return out;
}

void checkName(const std::string& name, const std::string& what, bool noDot) {
  if (name.empty()) throw InputError("a " + what + " needs a non-empty name");
  if (noDot && name.find('.') != std::string::npos)
    throw InputError(what + " " + q(name) + ": names with a '.' are reserved for the features cuts create");
}

int indexNamed(const Json& array, const std::string& name) {
  for (size_t i = 0; i < array.size(); ++i)
    if (array[i].is_object() && textOf(array[i], "name") == name) return static_cast<int>(i);
  return -1;
}

void notFound(const std::string& what, const std::string& name, const std::vector<std::string>& names) {
  throw InputError("no " + what + " " + q(name) + didYouMean(name, names));
}

void applyEdit(Json& root, const SceneEdit& edit) {
  if (!root.is_object()) throw InputError("the scene is not a JSON object");
  std::visit(Overloaded{[&](const AddKey&) { applyKeyEdit(root, edit); }, [&](const RemoveKey&) { applyKeyEdit(root, edit); },
                        [&](const RenameKey&) { applyKeyEdit(root, edit); }, [&](const MoveKey&) { applyKeyEdit(root, edit); },
                        [&](const SetReference&) { applyKeyEdit(root, edit); },
                        [&](const SetKeyDrawing&) { applyKeyEdit(root, edit); },
                        [&](const SetFeature&) { applyKeyEdit(root, edit); },
                        [&](const RemoveFeature&) { applyKeyEdit(root, edit); },
                        [&](const RenameFeature&) { applyKeyEdit(root, edit); },
                        [&](const SetInteriorFeature&) { applyKeyEdit(root, edit); },
                        [&](const RemoveInteriorFeature&) { applyKeyEdit(root, edit); },
                        [&](const RenameInteriorFeature&) { applyKeyEdit(root, edit); },
                        [&](const SetInteriorRadius&) { applyKeyEdit(root, edit); },
                        [&](const AddMark&) { applyMarkEdit(root, edit); }, [&](const MoveMark&) { applyMarkEdit(root, edit); },
                        [&](const RemoveMark&) { applyMarkEdit(root, edit); },
                        [&](const SetMarkKey&) { applyMarkEdit(root, edit); },
                        [&](const SetMarkEase&) { applyMarkEdit(root, edit); },
                        [&](const SetParameter&) { applyMarkEdit(root, edit); },
                        [&](const ResetParameter&) { applyMarkEdit(root, edit); },
                        [&](const auto&) { applyCutEdit(root, edit); }},
             edit);
}

void applyKeyEdit(Json& root, const SceneEdit& edit) {
  std::visit(
      Overloaded{
          [&](const AddKey& e) {
            checkName(e.name, "key", false);
            for (const std::string& existing : keyNames(root))
              if (existing == e.name) throw InputError("key " + q(e.name) + " exists already: choose another name");
            if (e.drawing.empty()) throw InputError("key " + q(e.name) + " needs a drawing (a PNG, relative to the scene file)");
            Json& list = keys(root);
            const int at = e.index < 0 ? static_cast<int>(list.size()) : e.index;
            if (at > static_cast<int>(list.size()))
              throw InputError("key " + q(e.name) + ": place " + std::to_string(at) + " is past the " +
                               std::to_string(list.size()) + " keys");
            list.insert(list.begin() + at, Json{{"name", e.name}, {"drawing", e.drawing}});
          },
          [&](const RemoveKey& e) {
            Json& list = keys(root);
            const int at = indexNamed(list, e.name);
            if (at < 0) notFound("key", e.name, keyNames(root));
            list.erase(static_cast<size_t>(at));
            renameKeyUses(root, e.name, "");
          },
          [&](const RenameKey& e) {
            checkName(e.to, "key", false);
            Json& renamed = key(root, e.from);
            for (const std::string& existing : keyNames(root))
              if (existing == e.to) throw InputError("key " + q(e.to) + " exists already: choose another name");
            renamed["name"] = e.to;
            renameKeyUses(root, e.from, e.to);
          },
          [&](const MoveKey& e) {
            Json& list = keys(root);
            const int from = indexNamed(list, e.name);
            if (from < 0) notFound("key", e.name, keyNames(root));
            if (e.index < 0 || e.index >= static_cast<int>(list.size()))
              throw InputError("key " + q(e.name) + ": place " + std::to_string(e.index) + " is not one of 0.." +
                               std::to_string(list.size() - 1));
            Json moved = list[static_cast<size_t>(from)];
            list.erase(static_cast<size_t>(from));
            list.insert(list.begin() + e.index, std::move(moved));
          },
          [&](const SetReference& e) {
            key(root, e.key);
            root["reference"] = e.key;
          },
          [&](const SetKeyDrawing& e) {
            if (e.drawing.empty()) throw InputError("key " + q(e.key) + " needs a drawing (a PNG, relative to the scene file)");
            key(root, e.key)["drawing"] = e.drawing;
          },
          [&](const SetFeature& e) {
            checkName(e.name, "feature", false);
            objectField(key(root, e.key), "features")[e.name] = pointJson(e.at);
          },
          [&](const RemoveFeature& e) { removeNamed(root, "features", "feature", e.name, e.key); },
          [&](const RenameFeature& e) {
            checkName(e.to, "feature", false);
            renameNamed(root, "features", "feature", e.from, e.to);
          },
          [&](const SetInteriorFeature& e) {
            checkName(e.name, "interior feature", true);
            if (e.radius && !(*e.radius >= kMinInteriorRadius && *e.radius <= kMaxInteriorRadius))
              throw InputError("interior feature " + q(e.name) + ": radius " + shortestText(*e.radius) + " px is out of range [" +
                               shortestText(kMinInteriorRadius) + ", " + shortestText(kMaxInteriorRadius) + "]");
            Json value = pointJson(e.at);
            if (e.radius) value = Json{{"at", value}, {"radius", pointJson({*e.radius, 0})[0]}};
            objectField(key(root, e.key), "interior_features")[e.name] = value;
          },
          [&](const RemoveInteriorFeature& e) { removeNamed(root, "interior_features", "interior feature", e.name, e.key); },
          [&](const RenameInteriorFeature& e) {
            checkName(e.to, "interior feature", true);
            renameNamed(root, "interior_features", "interior feature", e.from, e.to);
          },
          [&](const SetInteriorRadius& e) {
            if (!(e.radius >= kMinInteriorRadius && e.radius <= kMaxInteriorRadius))
              throw InputError("interior feature " + q(e.name) + ": radius " + shortestText(e.radius) + " px is out of range [" +
                               shortestText(kMinInteriorRadius) + ", " + shortestText(kMaxInteriorRadius) + "]");
            std::vector<Json*> placing;  // the feature's value in each key that places it
            std::vector<std::string> known;
            for (Json& k : keys(root)) {
              if (!k.contains("interior_features") || !k["interior_features"].is_object()) continue;
              Json& object = k["interior_features"];
              for (auto it = object.begin(); it != object.end(); ++it) known.push_back(it.key());
              if (object.contains(e.name)) placing.push_back(&object[e.name]);
            }
            if (placing.empty()) notFound("interior feature", e.name, known);
            const Json radius = pointJson({e.radius, 0})[0];
            bool given = false;
            for (Json* value : placing)
              if (value->is_object() && value->contains("radius")) (*value)["radius"] = radius, given = true;
            if (given) return;
            Json& first = *placing.front();  // a bare point, or {"at": [x, y]} without a radius
            if (first.is_object()) first["radius"] = radius;
            else first = Json{{"at", first}, {"radius", radius}};
          },
          [&](const auto&) { throw std::logic_error("applyKeyEdit: not a key edit"); }},
      edit);
}

std::string describe(const SceneEdit& edit) {
  std::ostringstream out;
  std::visit(
      Overloaded{
          [&](const AddKey& e) { out << "add key " << q(e.name); },
          [&](const RemoveKey& e) { out << "remove key " << q(e.name); },
          [&](const RenameKey& e) { out << "rename key " << q(e.from) << " to " << q(e.to); },
          [&](const MoveKey& e) { out << "move key " << q(e.name) << " to place " << e.index; },
          [&](const SetReference& e) { out << "make key " << q(e.key) << " the reference"; },
          [&](const SetKeyDrawing& e) { out << "draw key " << q(e.key) << " from " << e.drawing; },
          [&](const SetFeature& e) { out << "place feature " << q(e.name) << " in key " << q(e.key); },
          [&](const RemoveFeature& e) { out << "remove feature " << q(e.name); },
          [&](const RenameFeature& e) { out << "rename feature " << q(e.from) << " to " << q(e.to); },
          [&](const SetInteriorFeature& e) { out << "place interior feature " << q(e.name) << " in key " << q(e.key); },
          [&](const RemoveInteriorFeature& e) { out << "remove interior feature " << q(e.name); },
          [&](const RenameInteriorFeature& e) { out << "rename interior feature " << q(e.from) << " to " << q(e.to); },
          [&](const SetInteriorRadius& e) { out << "set the radius of interior feature " << q(e.name) << " to " << shortestText(e.radius) << " px"; },
          [&](const AddCut& e) { out << "add " << e.kind << " cut " << q(e.name) << " in key " << q(e.key); },
          [&](const RemoveCut& e) { out << "remove cut " << q(e.name); },
          [&](const RenameCut& e) { out << "rename cut " << q(e.from) << " to " << q(e.to); },
          [&](const MoveCutPoint& e) { out << "move point " << e.index + 1 << " of cut " << q(e.cut); },
          [&](const InsertCutPoint& e) { out << "add a point to cut " << q(e.cut); },
          [&](const RemoveCutPoint& e) { out << "remove point " << e.index + 1 << " of cut " << q(e.cut); },
          [&](const AddHole& e) { out << "mark a hole in key " << q(e.key); },
          [&](const MoveHole& e) { out << "move hole " << e.index + 1 << " of key " << q(e.key); },
          [&](const RemoveHole& e) { out << "remove hole " << e.index + 1 << " of key " << q(e.key); },
          [&](const AddStiffnessRegion& e) { out << "add stiffness region " << q(e.name); },
          [&](const AddStiffnessStroke& e) { out << "add stiffness stroke " << q(e.name); },
          [&](const RemoveStiffness& e) { out << "remove stiffness " << q(e.name); },
          [&](const RenameStiffness& e) { out << "rename stiffness " << q(e.from) << " to " << q(e.to); },
          [&](const MoveStiffnessPoint& e) { out << "move point " << e.index + 1 << " of stiffness " << q(e.name); },
          [&](const SetStiffnessKappa& e) { out << "set the kappa of stiffness " << q(e.name); },
          [&](const ScaleStiffness& e) { out << "scale every stiffness by " << e.factor; },
          [&](const AddMark& e) { out << "add a mark at " << e.time << " s"; },
          [&](const MoveMark& e) { out << "move mark " << e.index + 1 << " to " << e.time << " s"; },
          [&](const RemoveMark& e) { out << "remove mark " << e.index + 1; },
          [&](const SetMarkKey& e) { out << "mark " << e.index + 1 << " shows key " << q(e.key); },
          [&](const SetMarkEase& e) { out << "ease mark " << e.index + 1 << (e.ease.empty() ? " linearly" : " " + e.ease); },
          [&](const SetCutRelease& e) {
            out << "cut " << q(e.cut) << " lets go at " << (e.release ? std::to_string(*e.release) : std::string("the scene's release"));
          },
          [&](const SetParameter& e) { out << "set " << e.name; },
          [&](const ResetParameter& e) { out << "reset " << e.name; }},
      edit);
  return out.str();
}

}  // namespace ib::edit
