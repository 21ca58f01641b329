#include "playback/live_parameters.h"

#include "core/error.h"
#include "scene/scene_document.h"

#include <algorithm>
#include <cmath>

namespace ib::play {

namespace {

// The epsilon the dynamics toggle turns on with when the scene has no dynamics: half the
// compliance range, visible secondary motion without the largest swings.
constexpr double kDefaultEpsilon = 0.5;
// The lower end of a log slider whose range is open at 0 (tau, anchor, gust_frequency,
// max_deviation): far below any value the bundled scenes use (tau down to 1e-9); typed entry takes
// smaller ones.
constexpr double kLogFloor = 1e-12;

Control control(const ParameterSpec& spec, double initial) {
  Control c;
  c.spec = &spec;
  c.value = c.initial = initial;
  double lo = spec.min, hi = spec.max;
  if (spec.logScale && spec.min > 0) {
    c.scale.kind = SliderScale::Kind::kLog;
  } else if (spec.logScale && spec.minOpen) {
    c.scale.kind = SliderScale::Kind::kLog;
    lo = kLogFloor;
  } else if (spec.logScale) {
    c.scale.kind = SliderScale::Kind::kSymmetricLog;
    c.scale.c = spec.defaultValue != 0 ? 1e-3 * std::abs(spec.defaultValue) : 1e-3;
  } else if (spec.minOpen) {
    lo = spec.min + 1e-3 * (spec.max - spec.min);
  }
  if (c.scale.kind != SliderScale::Kind::kLog || initial > 0) lo = std::min(lo, initial);
  hi = std::max(hi, initial);
  c.sliderMin = c.scale.toSlider(lo);
  c.sliderMax = c.scale.toSlider(hi);
  return c;
}

}  // namespace

double SliderScale::toSlider(double value) const {
  switch (kind) {
    case Kind::kLog: return std::log10(value);
    case Kind::kSymmetricLog: return std::copysign(std::log10(1 + std::abs(value) / c), value);
    case Kind::kLinear: break;
  }
  return value;
}

double SliderScale::fromSlider(double s) const {
  switch (kind) {
    case Kind::kLog: return std::pow(10.0, s);
    case Kind::kSymmetricLog: return std::copysign(c * (std::pow(10.0, std::abs(s)) - 1), s);
    case Kind::kLinear: break;
  }
  return s;
}

LiveParameters::LiveParameters(const Scene& scene) {
  for (const ParameterSpec& spec : parameterTable()) {
    if (!spec.live) continue;
    double initial = spec.get ? spec.get(scene) : spec.defaultValue;
    if (spec.name == "dynamics") initial = scene.dynamics.enabled() ? 1 : 0;
    if (spec.name == "epsilon" && !scene.dynamics.enabled()) initial = kDefaultEpsilon;
    controls_.push_back(control(spec, initial));
  }
}

const std::vector<Control>& LiveParameters::all() const { return controls_; }

const Control& LiveParameters::find(const std::string& name) const {
  for (const Control& c : controls_)
    if (c.spec->name == name || (!c.spec->field.empty() && findParameter(name) == c.spec)) return c;
  const ParameterSpec& spec = parameter(name);  // unknown: "did you mean"
  throw InputError(inQuotes(spec.name) + " is not a control of the player: it " +
                   (spec.invalidates == Invalidates::kMultimesh ? "changes the multimesh" : "is not live") +
                   "; set it in the scene file (" + spec.field + ") or with `inbetween render --set`");
}

Control& LiveParameters::find(const std::string& name) {
  return const_cast<Control&>(static_cast<const LiveParameters&>(*this).find(name));
}

void LiveParameters::set(const std::string& name, double value) {
  Control& c = find(name);
  checkParameterValue(*c.spec, value, "parameter " + inQuotes(c.spec->name));
  if (c.value == value) return;
  c.value = value;
  ++generation_;
}

double LiveParameters::get(const std::string& name) const { return find(name).value; }

void LiveParameters::reset(const std::string& name) {
  Control& c = find(name);
  if (c.value == c.initial) return;
  c.value = c.initial;
  ++generation_;
}

void LiveParameters::resetAll() {
  for (const Control& c : controls_) reset(c.spec->name);
}

int LiveParameters::generation() const { return generation_; }

void LiveParameters::setFromText(const std::string& assignment) {
  const size_t equals = assignment.find('=');
  const std::string where = "--set " + inQuotes(assignment);
  if (equals == std::string::npos || equals == 0) throw InputError(where + ": expected NAME=VALUE, e.g. tau=1e-4");
  try {
    const Control& c = find(assignment.substr(0, equals));
    set(c.spec->name, parseParameterText(*c.spec, assignment.substr(equals + 1), where));
  } catch (const InputError& error) {
    const std::string message = error.what();
    throw InputError(message.rfind(where, 0) == 0 ? message : where + ": " + message);
  }
}

Scene LiveParameters::scene(const Scene& base) const {
  Scene out = base;
  for (const Control& c : controls_)
    if (c.spec->set) c.spec->set(out, c.value);
  return out;
}

FrameOptions LiveParameters::frameOptions() const {
  FrameOptions options;
  options.kappaScale = get("kappa_scale");
  options.dynamics = get("dynamics") != 0;
  return options;
}

std::vector<edit::SceneEdit> LiveParameters::saveEdits(const SceneDocument& document) const {
  std::vector<edit::SceneEdit> out;
  const bool dynamics = get("dynamics") != 0;
  for (const Control& c : controls_) {
    if (c.spec->field.empty()) continue;
    const double value = c.spec->name == "epsilon" && !dynamics ? 0.0 : c.value;
    if (document.parameter(c.spec->name) != value) out.push_back(edit::SetParameter{c.spec->name, value});
  }
  const double scale = get("kappa_scale");
  if (scale != savedKappaScale_) out.push_back(edit::ScaleStiffness{scale / savedKappaScale_});
  return out;
}

void LiveParameters::markSaved() { savedKappaScale_ = get("kappa_scale"); }

void LiveParameters::saveInto(SceneDocument& document) {
  for (const edit::SceneEdit& e : saveEdits(document)) document.apply(e);
  markSaved();
}

}  // namespace ib::play
