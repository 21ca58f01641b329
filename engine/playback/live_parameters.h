// Every parameter the paper exposes, as the player's sliders and toggles: the solver's (tau,
// alpha, lambda, non-overlap), the painted stiffness' scale and the dynamics' (on/off, epsilon,
// mu, gravity, wind, anchor). Values start from the scene; the UI and `--set NAME=VALUE` change
// them; every change bumps generation() so the solve worker knows to resend.
#pragma once

#include "animation/dynamics.h"
#include "interpolation/interpolator.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace ib::play {

struct Parameter {
  std::string name;         // as in `--set NAME=VALUE` and the UI label: tau, alpha, lambda, kappa_scale,
                            // non_overlap, dynamics, epsilon, mu, gravity_x, gravity_y, wind_x, wind_y, anchor
  double value = 0;         // current
  double initial = 0;       // the scene's value (what reset() restores; the UI shows it as the default)
  double min = 0, max = 1;  // slider range, inclusive; widened to hold the scene's value when it lies outside
  bool toggle = false;      // 0/1 (non_overlap, dynamics)
  bool logScale = false;    // the UI's slider moves in log(value); min > 0 then
  std::string help;         // one line: what it does, units
};

class LiveParameters {
 public:
  // Values and initials from the scene: dynamics on when its epsilon > 0. The epsilon slider
  // starts at the scene's epsilon, or at 0.5 when the scene has none (what switching dynamics on
  // then gives); kappa_scale starts at 1 (the painted stiffness as the scene paints it).
  explicit LiveParameters(const Scene& scene);

  const std::vector<Parameter>& all() const;  // in the order listed in Parameter::name
  // InputError naming the parameter and its range for an unknown name, a non-finite value or one
  // out of range (toggles take 0 or 1). Setting the current value changes nothing.
  void set(const std::string& name, double value);
  double get(const std::string& name) const;  // InputError for an unknown name
  void reset(const std::string& name);        // back to its initial value
  void resetAll();

  InterpolationParams interpolation() const;  // tau, alpha, lambda, non_overlap
  DynamicsParams dynamics() const;            // the scene's other dynamics fields, epsilon 0 when `dynamics` is off
  double kappaScale() const;                  // multiplies the painted stiffness, > 0
  int generation() const;                     // +1 on every change (the UI compares it to resend)

  // Parses `NAME=VALUE` (the --set option), VALUE a number (toggles also on/off, true/false);
  // InputError naming the text.
  void setFromText(const std::string& assignment);

 private:
  Parameter& find(const std::string& name);
  const Parameter& find(const std::string& name) const;

  std::vector<Parameter> parameters_;
  DynamicsParams sceneDynamics_;  // the fields no slider moves (gust, settle, max deviation)
  int generation_ = 0;
};

}  // namespace ib::play
