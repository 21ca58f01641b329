#include "playback/live_parameters.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ib::play {

namespace {

// The epsilon the dynamics toggle turns on with when the scene has no dynamics: half the
// compliance range, visible secondary motion without the largest swings.
constexpr double kDefaultEpsilon = 0.5;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

Parameter slider(const std::string& name, double initial, double min, double max, bool logScale,
                 const std::string& help) {
  Parameter p;
  p.name = name;
  p.value = p.initial = initial;
  p.min = std::min(min, initial);
  p.max = std::max(max, initial);
  p.logScale = logScale && p.min > 0;
  p.help = help;
  return p;
}

Parameter toggle(const std::string& name, bool initial, const std::string& help) {
  Parameter p = slider(name, initial ? 1 : 0, 0, 1, false, help);
  p.toggle = true;
  return p;
}

std::string rangeText(const Parameter& p) {
  return p.toggle ? "0 (off) or 1 (on)" : "[" + number(p.min) + ", " + number(p.max) + "]";
}

}  // namespace

LiveParameters::LiveParameters(const Scene& scene) : sceneDynamics_(scene.dynamics) {
  const SceneSolverParams& s = scene.solver;
  const DynamicsParams& d = scene.dynamics;
  parameters_ = {
      slider("tau", s.tau, 1e-6, 1, true, "cohesive threshold: a glued pair lets go above it (normalized energy)"),
      slider("alpha", s.alpha, 0, 1, false, "cohesive pairs resist stretch (1) versus shear (0)"),
      slider("lambda", s.lambda, 1, 1e6, true, "cohesive stiffness: how hard glued cuts hold shut (per normalized length)"),
      slider("kappa_scale", 1, 0.01, 100, true, "multiplies every triangle's stiffness kappa against the cohesive pull"),
      toggle("non_overlap", s.nonOverlap, "keep the shape from overlapping itself (W_O)"),
      toggle("dynamics", d.enabled(), "secondary motion: follow-through, gravity, wind"),
      slider("epsilon", d.enabled() ? d.epsilon : kDefaultEpsilon, 0, 1, false,
             "compliance: 0 follows the keys exactly, 1 allows the most secondary motion"),
      slider("mu", d.mu, 0, 10, false, "damping of the secondary motion, 1/s"),
      slider("gravity_x", d.gravity.x(), -10, 10, false, "gravity, x (right), shape sizes per s^2"),
      slider("gravity_y", d.gravity.y(), -10, 10, false, "gravity, y (down), shape sizes per s^2"),
      slider("wind_x", d.wind.x(), -10, 10, false, "wind, x (right), shape sizes per s^2"),
      slider("wind_y", d.wind.y(), -10, 10, false, "wind, y (down), shape sizes per s^2"),
      slider("anchor", d.anchor, 1e-3, 10, true, "how strongly the shape keeps to the animation, relative to its stiffness"),
  };
}

const std::vector<Parameter>& LiveParameters::all() const { return parameters_; }

const Parameter& LiveParameters::find(const std::string& name) const {
  for (const Parameter& p : parameters_)
    if (p.name == name) return p;
  std::string names;
  for (const Parameter& p : parameters_) names += (names.empty() ? "" : ", ") + p.name;
  throw InputError("unknown parameter " + inQuotes(name) + " (one of " + names + ")");
}

Parameter& LiveParameters::find(const std::string& name) {
  return const_cast<Parameter&>(static_cast<const LiveParameters&>(*this).find(name));
}

void LiveParameters::set(const std::string& name, double value) {
  Parameter& p = find(name);
  const bool inRange = p.toggle ? (value == 0 || value == 1) : (value >= p.min && value <= p.max);
  if (!std::isfinite(value) || !inRange)
    throw InputError("parameter " + inQuotes(name) + ": " + number(value) + " is out of range " + rangeText(p));
  if (p.value == value) return;
  p.value = value;
  ++generation_;
}

double LiveParameters::get(const std::string& name) const { return find(name).value; }

void LiveParameters::reset(const std::string& name) {
  Parameter& p = find(name);
  if (p.value == p.initial) return;
  p.value = p.initial;
  ++generation_;
}

void LiveParameters::resetAll() {
  for (const Parameter& p : parameters_) reset(p.name);
}

InterpolationParams LiveParameters::interpolation() const {
  InterpolationParams out;
  out.cohesive.tau = get("tau");
  out.cohesive.alpha = get("alpha");
  out.cohesive.lambda = get("lambda");
  out.nonOverlap = get("non_overlap") != 0;
  return out;
}

DynamicsParams LiveParameters::dynamics() const {
  DynamicsParams out = sceneDynamics_;
  out.epsilon = get("dynamics") != 0 ? get("epsilon") : 0;
  out.mu = get("mu");
  out.gravity = {get("gravity_x"), get("gravity_y")};
  out.wind = {get("wind_x"), get("wind_y")};
  out.anchor = get("anchor");
  return out;
}

double LiveParameters::kappaScale() const { return get("kappa_scale"); }
int LiveParameters::generation() const { return generation_; }

void LiveParameters::setFromText(const std::string& assignment) {
  const size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw InputError("--set " + inQuotes(assignment) + ": expected NAME=VALUE, e.g. tau=1e-4");
  const std::string name = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  try {
    const Parameter& p = find(name);
    double value = 0;
    if (p.toggle && (text == "on" || text == "true")) {
      value = 1;
    } else if (p.toggle && (text == "off" || text == "false")) {
      value = 0;
    } else {
      char* end = nullptr;
      value = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size()) throw InputError(inQuotes(text) + " is not a number");
    }
    set(name, value);
  } catch (const InputError& error) {
    throw InputError("--set " + inQuotes(assignment) + ": " + error.what());
  }
}

}  // namespace ib::play
