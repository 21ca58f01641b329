#include "scene/parameter_json.h"

#include "core/error.h"
#include "core/suggest.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace ib {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;
using namespace json_fields;

// "solver.tau" -> {"solver", "tau"}; "sampling" -> {"", "sampling"}.
std::pair<std::string, std::string> splitField(const std::string& field) {
  const size_t dot = field.find('.');
  if (dot == std::string::npos) return {"", field};
  return {field.substr(0, dot), field.substr(dot + 1)};
}

// "X" is not "a" (meaning), "b" (meaning) or "c" (meaning) (did you mean "a"?).
std::string notAChoice(const ParameterSpec& spec, const std::string& word) {
  std::string list;
  std::vector<std::string> words;
  for (size_t i = 0; i < spec.choices.size(); ++i) {
    if (i > 0) list += i + 1 == spec.choices.size() ? " or " : ", ";
    list += inQuotes(spec.choices[i].word) + " (" + spec.choices[i].meaning + ")";
    words.push_back(spec.choices[i].word);
  }
  return inQuotes(word) + " is not " + list + didYouMean(word, words);
}

// The whole field of a parameter without components.
double readWhole(const json& v, const ParameterSpec& spec, const Context& here) {
  const std::string where = here.file + ": " + here.where;
  switch (spec.kind) {
    case ParameterKind::kToggle:
      if (!v.is_boolean()) throw here.error("must be true or false");
      return v.get<bool>() ? 1 : 0;
    case ParameterKind::kChoice: {
      if (!v.is_string()) throw here.error("must be one of the words " + formatParameterRange(spec));
      const std::string word = v.get<std::string>();
      for (size_t i = 0; i < spec.choices.size(); ++i)
        if (spec.choices[i].word == word) return double(i);
      throw here.error(notAChoice(spec, word));
    }
    case ParameterKind::kColor: {
      const bool ok = v.is_array() && v.size() == 3 && std::all_of(v.begin(), v.end(), [](const json& c) {
                        return c.is_number_integer() && c.get<long long>() >= 0 && c.get<long long>() <= 255;
                      });
      if (!ok) throw here.error("must be [r, g, b], each 0..255");
      return double(v[0].get<int>() * 65536 + v[1].get<int>() * 256 + v[2].get<int>());
    }
    case ParameterKind::kInteger:
    case ParameterKind::kNumber: {
      if (!v.is_number()) throw here.error(spec.kind == ParameterKind::kInteger ? "must be a whole number" : "must be a number");
      const double x = v.get<double>();
      if (spec.kind == ParameterKind::kInteger && std::isfinite(x) && x != std::floor(x))
        throw here.error("must be a whole number");
      checkParameterValue(spec, x, where);
      return x;
    }
  }
  return 0;
}

// The section object for writing, created when absent (or replaced when not an object).
ordered_json& sectionFor(ordered_json& root, const std::string& section) {
  if (section.empty()) return root;
  if (!root.contains(section) || !root[section].is_object()) root[section] = ordered_json::object();
  return root[section];
}

// A number as the file would say it: whole numbers without a fraction (24, not 24.0).
ordered_json numberJson(double value) {
  if (std::floor(value) == value && std::fabs(value) < 1e15) return ordered_json(static_cast<long long>(value));
  return ordered_json(value);
}

ordered_json valueJson(const ParameterSpec& spec, double value) {
  switch (spec.kind) {
    case ParameterKind::kToggle: return ordered_json(value != 0);
    case ParameterKind::kChoice: return ordered_json(spec.choices.at(static_cast<size_t>(value)).word);
    case ParameterKind::kColor: {
      const int c = static_cast<int>(value);
      return ordered_json::array({c >> 16, (c >> 8) & 255, c & 255});
    }
    case ParameterKind::kInteger:
    case ParameterKind::kNumber: return numberJson(value);
  }
  return numberJson(value);
}

// The default of the other component of spec's [x, y] field.
double otherDefault(const ParameterSpec& spec) {
  for (const ParameterSpec& other : parameterTable())
    if (other.field == spec.field && other.component >= 0 && other.component != spec.component) return other.defaultValue;
  return 0;
}

}  // namespace

std::set<std::string> parameterFields(const std::string& section) {
  std::set<std::string> fields;
  for (const ParameterSpec& spec : parameterTable()) {
    if (spec.field.empty()) continue;
    const auto [s, key] = splitField(spec.field);
    if (s == section) fields.insert(key);
  }
  return fields;
}

void readParameters(const json& root, const Context& at, Scene& scene) {
  for (const ParameterSpec& spec : parameterTable()) {
    if (spec.field.empty()) continue;
    const auto [section, key] = splitField(spec.field);
    const json* holder = &root;
    Context here = at;
    if (!section.empty()) {
      if (!root.contains(section) || !root[section].is_object()) continue;
      holder = &root[section];
      here = here.in(section);
    }
    if (!holder->contains(key)) continue;
    const json& v = (*holder)[key];
    here = here.in(key);
    double value = 0;
    if (spec.component < 0) {
      value = readWhole(v, spec, here);
    } else {
      if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
        throw here.error("must be a point [x, y] in " + spec.unit + " (y down)");
      value = v[spec.component].get<double>();
      checkParameterValue(spec, value, here.file + ": " + here.where + ": " + (spec.component == 0 ? "x" : "y"));
    }
    spec.set(scene, value);
  }
}

void writeParameter(ordered_json& root, const ParameterSpec& spec, double value) {
  if (spec.field.empty()) throw std::logic_error("parameter " + spec.name + " has no field in the scene file");
  const auto [section, key] = splitField(spec.field);
  ordered_json& holder = sectionFor(root, section);
  if (spec.component < 0) {
    if (spec.kind == ParameterKind::kColor && value < 0) holder.erase(key);
    else holder[key] = valueJson(spec, value);
    return;
  }
  ordered_json& point = holder[key];
  if (!point.is_array() || point.size() != 2) {
    const double other = otherDefault(spec);
    point = spec.component == 0 ? ordered_json::array({numberJson(value), numberJson(other)})
                                : ordered_json::array({numberJson(other), numberJson(value)});
  } else {
    point[static_cast<size_t>(spec.component)] = numberJson(value);
  }
}

void removeParameter(ordered_json& root, const ParameterSpec& spec) {
  if (spec.field.empty()) return;
  const auto [section, key] = splitField(spec.field);
  ordered_json* holder = &root;
  if (!section.empty()) {
    if (!root.contains(section) || !root[section].is_object()) return;
    holder = &root[section];
  }
  if (!holder->contains(key)) return;
  if (spec.component >= 0) {
    ordered_json& point = (*holder)[key];
    const double other = otherDefault(spec);
    const bool otherAtDefault = point.is_array() && point.size() == 2 && point[1 - spec.component].is_number() &&
                                point[1 - spec.component].get<double>() == other;
    if (!otherAtDefault && point.is_array() && point.size() == 2) {
      point[static_cast<size_t>(spec.component)] = numberJson(spec.defaultValue);
      return;
    }
  }
  holder->erase(key);
  if (!section.empty() && holder->empty()) root.erase(section);
}

double parameterIn(const ordered_json& root, const ParameterSpec& spec) {
  if (spec.field.empty()) return spec.defaultValue;
  const auto [section, key] = splitField(spec.field);
  const ordered_json* holder = &root;
  if (!section.empty()) {
    if (!root.contains(section) || !root[section].is_object()) return spec.defaultValue;
    holder = &root[section];
  }
  if (!holder->contains(key)) return spec.defaultValue;
  const ordered_json& v = (*holder)[key];
  if (spec.component >= 0)
    return v.is_array() && v.size() == 2 && v[spec.component].is_number() ? v[spec.component].get<double>() : spec.defaultValue;
  switch (spec.kind) {
    case ParameterKind::kToggle: return v.is_boolean() && v.get<bool>() ? 1 : 0;
    case ParameterKind::kChoice:
      if (v.is_string())
        for (size_t i = 0; i < spec.choices.size(); ++i)
          if (spec.choices[i].word == v.get<std::string>()) return double(i);
      return spec.defaultValue;
    case ParameterKind::kColor:
      return v.is_array() && v.size() == 3 && v[0].is_number_integer() && v[1].is_number_integer() && v[2].is_number_integer()
                 ? double(v[0].get<int>() * 65536 + v[1].get<int>() * 256 + v[2].get<int>())
                 : spec.defaultValue;
    case ParameterKind::kInteger:
    case ParameterKind::kNumber: return v.is_number() ? v.get<double>() : spec.defaultValue;
  }
  return spec.defaultValue;
}

}  // namespace ib
