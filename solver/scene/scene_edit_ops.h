// The scene document's edits on its JSON (for scene_document.cpp and the edit files): applyEdit
// dispatches, each group of edits lives in its own file, and the helpers here find what an edit
// names or say what is missing. Every function throws InputError, changing nothing the caller
// keeps, when the edit cannot apply.
#pragma once

#include "scene/scene_edits.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ib::edit {

using Json = nlohmann::ordered_json;

// Applies `edit` to a scene file's JSON object.
void applyEdit(Json& root, const SceneEdit& edit);

// The groups (scene_edits.cpp: keys and features; scene_edit_cuts.cpp: cuts, holes, stiffness;
// scene_edit_marks.cpp: marks and parameters).
void applyKeyEdit(Json& root, const SceneEdit& edit);
void applyCutEdit(Json& root, const SceneEdit& edit);
void applyMarkEdit(Json& root, const SceneEdit& edit);

// std::visit over the edit kinds a group handles, one lambda each.
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// Helpers shared by the groups. They read a document that may be malformed (it is validated only
// after an edit): a field of the wrong type reads as absent.
// The string field `field` of `j` (an object), or "" when it is absent or not a string.
std::string textOf(const Json& j, const char* field);
// The boolean field `field` of `j`, or `fallback`.
bool flagOf(const Json& j, const char* field, bool fallback);
inline std::string q(const std::string& name) { return "\"" + name + "\""; }  // a name in quotes
Json& keys(Json& root);                                    // the "keys" array (InputError when missing)
std::vector<std::string> keyNames(const Json& root);
Json& key(Json& root, const std::string& name);             // the key named `name`, or InputError (did you mean)
Json pointJson(const Point& p);                             // [x, y], rounded to 1/1000 px, whole numbers as such
Json pointsJson(const Points& points);
// Checks a name given to something new: non-empty, without '.' when dotted names are reserved.
void checkName(const std::string& name, const std::string& what, bool noDot);
// The index of the element of `array` (of objects) whose "name" is `name`, or -1.
int indexNamed(const Json& array, const std::string& name);
// InputError: `no WHAT "NAME" (did you mean ...)` over `names`.
[[noreturn]] void notFound(const std::string& what, const std::string& name, const std::vector<std::string>& names);

}  // namespace ib::edit
