// Every parameter a user can set, declared once: its name (as in `--set NAME=VALUE`, on the
// player's slider and in docs/parameters.md), where the scene file holds it, its unit, default,
// valid range, a one-line meaning, and what a change makes stale. The scene parser, `--set`,
// the player's sliders and Save, the scene document's edits, the player's reloader and the
// documentation all read this table (docs/parameters.md is checked against it by a test).
//
// Values are doubles: a toggle is 0 or 1, a choice the index of its word, a colour
// 65536 r + 256 g + b (or -1 for none).
#pragma once

#include <string>
#include <vector>

namespace ib {

struct Scene;  // scene/scene.h

enum class ParameterKind {
  kNumber,   // a real number
  kInteger,  // a whole number
  kToggle,   // on or off: true or false in the file
  kChoice,   // one of ParameterSpec::choices: a word in the file
  kColor,    // an RGB colour, [r, g, b] in the file, each 0..255; absent: none
};

// What a change to a parameter makes stale.
enum class Invalidates {
  kNothing,    // how frames are drawn or played: nothing is solved again
  kSolve,      // the frames: solved again on the same multimesh
  kMultimesh,  // the multimesh: traced, meshed and optimized again (its painted stiffness included)
};

struct ParameterChoice {
  std::string word;     // as in the file and in --set
  std::string meaning;  // a few words, for messages and the docs
};

struct ParameterSpec {
  std::string name;   // --set NAME, the player's label, the docs: "tau", "gravity_x"
  std::string field;  // where the scene file holds it, "solver.tau"; empty for the player's own
  int component = -1;  // 0 (x) or 1 (y) of an [x, y] field (gravity, wind); -1: the whole field
  ParameterKind kind = ParameterKind::kNumber;
  std::vector<ParameterChoice> choices;  // kChoice: the words, in the order of their values
  double defaultValue = 0;
  double min = 0, max = 0;  // the range the file, --set and the player accept, inclusive
  bool minOpen = false;     // (min, max]: min itself is not accepted
  bool zeroIsAuto = false;  // 0 is accepted as well, meaning "follow the drawings"
  bool logScale = false;    // the player's slider moves in log(value) (its range spans decades)
  std::string unit;         // "px", "1/s", "" for a pure number
  std::string meaning;      // one line
  Invalidates invalidates = Invalidates::kSolve;
  bool live = false;        // a control in the player's window
  // The value in a parsed Scene, and setting it there; null for the player's own parameters
  // (kappa_scale, dynamics), which no scene field holds. `set` writes the field alone: a
  // timeline setting (fps, loop, spacing) reaches Scene::timeline, and a multimesh field the
  // multimesh, only when the scene is parsed and built again (as --set does, through the
  // scene's document: scene/scene_document.h).
  double (*get)(const Scene&) = nullptr;
  void (*set)(Scene&, double) = nullptr;
};

// Every parameter, in the order of the docs: meshing and tracing, solver, timeline, dynamics,
// drawing, then the player's own.
const std::vector<ParameterSpec>& parameterTable();

// By name ("tau") or field ("solver.tau"; "dynamics.gravity.x" for a component): null when there is none.
const ParameterSpec* findParameter(const std::string& name);
// The same, or an InputError naming the unknown name, the nearest known one ("did you mean") and
// where the list is.
const ParameterSpec& parameter(const std::string& name);

// Whether `value` is one the parameter takes (finite, in its range; a choice's index, a toggle's
// 0 or 1, a colour's RRGGBB or -1).
bool parameterValueValid(const ParameterSpec& spec, double value);
// InputError unless `value` is one the parameter takes; `where` starts the message (e.g.
// `--set "tau=0"` or `scene.json: solver: tau`).
void checkParameterValue(const ParameterSpec& spec, double value, const std::string& where);
// A value from text (--set, a typed entry): a number (for a choice also its word, for a toggle
// also on / off / true / false, for a colour RRGGBB or none), checked. InputError naming `where`.
double parseParameterText(const ParameterSpec& spec, const std::string& text, const std::string& where);
// The value as --set takes it: "1e-09", "on", "per_key", "ff8800", "none".
std::string formatParameterValue(const ParameterSpec& spec, double value);
// The shortest text that reads back as `value` ("0.001", "23.976023976", "1e+06").
std::string shortestText(double value);

// The accepted values, for messages and the docs: "(0, 1e+06]", "on or off", "shared or per_key".
std::string formatParameterRange(const ParameterSpec& spec);

}  // namespace ib
