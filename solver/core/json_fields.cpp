#include "core/json_fields.h"

#include "core/suggest.h"

#include <cmath>

namespace ib::json_fields {

using nlohmann::json;

Context element(const json& j, const Context& parent, const std::string& what, size_t index) {
  if (j.is_object() && j.contains("name") && j["name"].is_string() && !j["name"].get<std::string>().empty())
    return parent.in(what + " " + inQuotes(j["name"].get<std::string>()));
  return parent.in(what + " " + std::to_string(index + 1));
}

void requireObject(const json& j, const Context& at, const std::set<std::string>& allowed) {
  if (!j.is_object()) throw at.error("must be a JSON object");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!allowed.count(it.key())) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      throw at.error("unknown field " + inQuotes(it.key()) + didYouMean(it.key(), {allowed.begin(), allowed.end()}) +
                     " (expected one of: " + list + ")");
    }
}

double number(const json& object, const std::string& key, double fallback, const Context& at, double lo, double hi,
              bool loOpen) {
  if (!object.contains(key)) return fallback;
  const json& v = object[key];
  const Context here = at.in(key);
  if (!v.is_number()) throw here.error("must be a number");
  const double x = v.get<double>();
  const bool low = loOpen ? x > lo : x >= lo;
  if (!std::isfinite(x) || !low || x > hi) {
    const std::string range = (loOpen ? "(" : "[") + json(lo).dump() + ", " + json(hi).dump() + "]";
    throw here.error(json(x).dump() + " is out of range " + range);
  }
  return x;
}

std::string text(const json& object, const std::string& key, const Context& at) {
  if (!object.contains(key)) throw at.error("missing field " + inQuotes(key));
  const json& v = object[key];
  if (!v.is_string() || v.get<std::string>().empty()) throw at.in(key).error("must be a non-empty string");
  return v.get<std::string>();
}

bool boolean(const json& object, const std::string& key, bool fallback, const Context& at) {
  if (!object.contains(key)) return fallback;
  if (!object[key].is_boolean()) throw at.in(key).error("must be true or false");
  return object[key].get<bool>();
}

Eigen::Vector2d point(const json& v, const Context& at, const std::string& meaning) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
    throw at.error("must be a point [x, y] " + meaning);
  const Eigen::Vector2d p(v[0].get<double>(), v[1].get<double>());
  if (!p.allFinite()) throw at.error("must be finite");
  return p;
}

}  // namespace ib::json_fields
