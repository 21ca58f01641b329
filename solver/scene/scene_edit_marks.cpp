// The scene document's edits of timeline marks and of parameters (the parameter table).
#include "scene/scene_edit_ops.h"

#include "animation/timeline.h"
#include "core/error.h"
#include "scene/parameter_json.h"
#include "scene/parameters.h"

#include <algorithm>
#include <cmath>

namespace ib::edit {

namespace {

std::string seconds(double time) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", time);
  return text;
}

Json timeJson(double time) {
  if (!std::isfinite(time)) throw InputError("timeline: a mark's time must be a finite number of seconds");
  const double rounded = std::round(time * 1e6) / 1e6;
  return rounded == std::floor(rounded) && std::fabs(rounded) < 1e9 ? Json(static_cast<long long>(rounded)) : Json(rounded);
}

// The "marks" array. A timeline without marks plays every key a second apart (defaultTimeline);
// before its first edit those marks are written out, so the edit changes that timeline.
Json& marks(Json& root) {
  if (!root.contains("timeline") || !root["timeline"].is_object()) root["timeline"] = Json::object();
  Json& timeline = root["timeline"];
  if (timeline.contains("marks") && timeline["marks"].is_array()) return timeline["marks"];
  const std::vector<std::string> names = keyNames(root);
  Json list = Json::array();
  if (!names.empty()) {
    const Timeline plain = defaultTimeline(names, Timeline().fps(), flagOf(timeline, "loop", false));
    for (size_t m = 0; m < plain.marks().size(); ++m) {
      Json mark = Json{{"time", timeJson(plain.marks()[m].time)}, {"key", plain.marks()[m].label}};
      if (m < plain.segments().size()) mark["ease"] = easingName(plain.segments()[m].easing.kind);
      list.push_back(std::move(mark));
    }
  }
  timeline["marks"] = std::move(list);
  return timeline["marks"];
}

double timeOf(const Json& mark) { return mark.contains("time") && mark["time"].is_number() ? mark["time"].get<double>() : 0; }

void checkMark(int index, const Json& list) {
  if (index < 0 || index >= static_cast<int>(list.size()))
    throw InputError("timeline: mark " + std::to_string(index + 1) + " is not one of 1.." + std::to_string(list.size()));
}

void checkKey(Json& root, const std::string& name) { key(root, name); }

// The last mark starts no segment: it takes no ease, blend or spacing.
void tidyLast(Json& list) {
  if (list.empty()) return;
  for (const char* field : {"ease", "blend", "spacing"}) list.back().erase(field);
}

}  // namespace

void applyMarkEdit(Json& root, const SceneEdit& edit) {
  std::visit(
      Overloaded{
          [&](const AddMark& e) {
            if (e.key.empty() == e.weights.empty())
              throw InputError("timeline: a new mark needs exactly one of a key and weights");
            const Json time = timeJson(e.time);  // as written: the order and the clash below are the file's
            Json mark = Json{{"time", time}};
            if (!e.key.empty()) {
              checkKey(root, e.key);
              mark["key"] = e.key;
            } else {
              Json weights = Json::object();
              double sum = 0;
              for (const auto& [name, w] : e.weights) {
                checkKey(root, name);
                if (!(w >= 0 && std::isfinite(w))) throw InputError("timeline: weight of key " + q(name) + " must be >= 0");
                weights[name] = w;
                sum += w;
              }
              if (!(sum > 0)) throw InputError("timeline: a breakdown needs a positive weight for at least one key");
              mark["weights"] = std::move(weights);
            }
            if (!e.ease.empty()) {
              Json ease = Json::parse(e.ease, nullptr, false);
              if (ease.is_discarded()) throw InputError("timeline: the new mark's ease is not JSON: " + e.ease);
              mark["ease"] = std::move(ease);
            }
            Json& list = marks(root);
            const auto at = std::find_if(list.begin(), list.end(), [&](const Json& m) { return timeOf(m) >= time.get<double>(); });
            if (at != list.end() && timeOf(*at) == time.get<double>())
              throw InputError("timeline: mark " + std::to_string(at - list.begin() + 1) + " is at " + seconds(e.time) +
                               " already: move it, or add this mark at another time");
            const bool last = at == list.end();
            if (!last && !mark.contains("ease")) mark["ease"] = "linear";
            if (last && !list.empty() && !list.back().contains("ease")) list.back()["ease"] = "linear";
            list.insert(at, std::move(mark));
          },
          [&](const MoveMark& e) {
            Json& list = marks(root);
            checkMark(e.index, list);
            const size_t i = static_cast<size_t>(e.index);
            const double time = timeJson(e.time).get<double>();
            if ((i > 0 && !(time > timeOf(list[i - 1]))) || (i + 1 < list.size() && !(time < timeOf(list[i + 1]))))
              throw InputError("timeline: mark " + std::to_string(e.index + 1) + " stays between its neighbours (" +
                               (i > 0 ? seconds(timeOf(list[i - 1])) : std::string("the start")) + " and " +
                               (i + 1 < list.size() ? seconds(timeOf(list[i + 1])) : std::string("the end")) +
                               "): " + seconds(e.time) + " is not");
            list[i]["time"] = timeJson(e.time);
          },
          [&](const RemoveMark& e) {
            Json& list = marks(root);
            checkMark(e.index, list);
            if (list.size() <= 1) throw InputError("timeline: the last mark stays: a timeline needs at least one");
            list.erase(static_cast<size_t>(e.index));
            tidyLast(list);
          },
          [&](const SetMarkKey& e) {
            Json& list = marks(root);
            checkMark(e.index, list);
            checkKey(root, e.key);
            Json& mark = list[static_cast<size_t>(e.index)];
            mark.erase("weights");
            mark["key"] = e.key;
          },
          [&](const SetMarkEase& e) {
            Json& list = marks(root);
            checkMark(e.index, list);
            Json& mark = list[static_cast<size_t>(e.index)];
            if (e.ease.empty()) {
              mark.erase("ease");
              return;
            }
            Json ease = Json::parse(e.ease, nullptr, false);
            if (ease.is_discarded()) throw InputError("timeline: mark " + std::to_string(e.index + 1) + "'s ease is not JSON: " + e.ease);
            mark["ease"] = std::move(ease);
          },
          [&](const SetParameter& e) {
            const ParameterSpec& spec = parameter(e.name);
            if (spec.field.empty())
              throw InputError(q(spec.name) + " is the player's own (a slider in `inbetween play`), not a field of the scene");
            checkParameterValue(spec, e.value, spec.name);
            writeParameter(root, spec, e.value);
          },
          [&](const ResetParameter& e) { removeParameter(root, parameter(e.name)); },
          [&](const auto&) { throw std::logic_error("applyMarkEdit: not a mark or parameter edit"); }},
      edit);
}

}  // namespace ib::edit
