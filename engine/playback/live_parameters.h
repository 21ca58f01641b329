// The player's controls: every parameter the table marks live (scene/parameters.h: the solver's,
// the dynamics', the player's own kappa_scale and dynamics toggle), as sliders, toggles and
// choices. Values start from the scene; the UI and `--set NAME=VALUE` change them; every change
// bumps generation() so the solve worker knows to resend. What they mean for the frames is the
// one mapping of pipeline/scene_frames.h, from scene() and frameOptions().
#pragma once

#include "pipeline/scene_frames.h"
#include "scene/parameters.h"
#include "scene/scene.h"
#include "scene/scene_edits.h"

#include <string>
#include <vector>

namespace ib {
class SceneDocument;
}

namespace ib::play {

// Where a number sits on its slider, which moves linearly in s: s = v (linear); s = log10(v)
// (log, for ranges open at 0 such as tau: from 1e-12); s = sign(v) log10(1 + |v| / c) (symmetric
// log, for log ranges that hold 0 or negative values, such as lambda, mu and gravity: about linear
// below c, logarithmic above).
struct SliderScale {
  enum class Kind { kLinear, kLog, kSymmetricLog };
  Kind kind = Kind::kLinear;
  double c = 1;  // kSymmetricLog: the value below which the slider is about linear, > 0
  double toSlider(double value) const;
  double fromSlider(double s) const;
};

struct Control {
  const ParameterSpec* spec = nullptr;  // name, range, unit, meaning: the table's row
  double value = 0;                     // current
  double initial = 0;                   // the scene's value (what reset() restores; the UI shows it)
  // The slider, for numbers: its scale and its ends in slider units. The ends cover the
  // parameter's whole range (an open end at 0 from 1e-12 on; typed entry reaches below),
  // widened to hold the scene's value.
  SliderScale scale;
  double sliderMin = 0, sliderMax = 1;
};

class LiveParameters {
 public:
  // Values and initials from the scene: dynamics on when its epsilon > 0; the epsilon control
  // starts at the scene's epsilon, or at 0.5 when the scene has none (what switching dynamics
  // on then gives); kappa_scale starts at 1 (the painted stiffness as the scene paints it).
  explicit LiveParameters(const Scene& scene);

  const std::vector<Control>& all() const;  // in the table's order
  // InputError naming the parameter and its range (the table's: what the scene file takes) for
  // an unknown name or a value it does not take. Setting the current value changes nothing.
  void set(const std::string& name, double value);
  double get(const std::string& name) const;  // InputError for an unknown name
  void reset(const std::string& name);        // back to its initial value
  void resetAll();
  int generation() const;  // +1 on every change (the UI compares it to resend)

  // `NAME=VALUE` (the --set option): VALUE as the table reads text (a number; a word for a
  // choice; on/off for a toggle). InputError naming the text, also for a parameter that is not
  // live, saying where to set it.
  void setFromText(const std::string& assignment);

  // `base` (the scene these controls were made from, or its reload) with every control's value.
  Scene scene(const Scene& base) const;
  // kappa_scale and the dynamics toggle, for sceneFrameSetup.
  FrameOptions frameOptions() const;

  // The player's Save: every control whose value differs from the document's is set in it (the
  // dynamics toggle off saves epsilon 0); kappa_scale, which no field holds, scales every
  // stiffness the scene names (edit::ScaleStiffness) by what it has moved since the last save
  // of these controls, so that saving twice before the reloaded scene comes back scales once.
  // InputError as the edits say; then nothing is counted as saved.
  void saveInto(SceneDocument& document);
  // The edits saveInto makes of `document`, for an owner that applies them itself (the editor's
  // document); markSaved() once they are applied.
  std::vector<edit::SceneEdit> saveEdits(const SceneDocument& document) const;
  void markSaved();

 private:
  Control& find(const std::string& name);
  const Control& find(const std::string& name) const;

  std::vector<Control> controls_;
  int generation_ = 0;
  double savedKappaScale_ = 1;  // the kappa_scale the scene file holds already (saveInto)
};

}  // namespace ib::play
