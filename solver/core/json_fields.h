// Reading validated fields from the scene's JSON. Every error names the file and the path of
// fields and names leading to the value, e.g. `walk.json: timeline: mark 3: time: ...`.
#pragma once

#include "core/error.h"

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace ib::json_fields {

// Where a value sits, for messages: the file, then the path of fields and names inside it.
struct Context {
  std::string file, where;

  Context in(const std::string& part) const { return {file, where.empty() ? part : where + ": " + part}; }
  InputError error(const std::string& what) const {
    return InputError(file + ": " + (where.empty() ? "" : where + ": ") + what);
  }
};

// Where an element of an array of objects sits, before it is validated: `what "NAME"` when it has a
// non-empty string "name", else `what N` (N from 1), e.g. `key "arch"` or `cut 2`.
Context element(const nlohmann::json& j, const Context& parent, const std::string& what, size_t index);

// Throws unless j is an object whose fields are all in `allowed`.
void requireObject(const nlohmann::json& j, const Context& at, const std::set<std::string>& allowed);

// A number in [lo, hi] (open at lo when loOpen), or the fallback when the field is absent.
double number(const nlohmann::json& object, const std::string& key, double fallback, const Context& at, double lo,
              double hi, bool loOpen = false);

// A required non-empty string field.
std::string text(const nlohmann::json& object, const std::string& key, const Context& at);

// true or false, or the fallback when the field is absent.
bool boolean(const nlohmann::json& object, const std::string& key, bool fallback, const Context& at);

// [x, y], finite. `meaning` completes "must be a point [x, y] ..." in the message.
Eigen::Vector2d point(const nlohmann::json& v, const Context& at, const std::string& meaning = "in drawing pixels");

}  // namespace ib::json_fields
