#include "scene/scene_document.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_layout.h"
#include "scene/parameter_json.h"
#include "scene/parameters.h"
#include "scene/scene_edit_ops.h"

#include <nlohmann/json.hpp>

namespace ib {

using Json = nlohmann::ordered_json;

namespace {

// The JSON as compact text; text that is not UTF-8 (a name typed in another encoding) is written
// with U+FFFD in its place rather than thrown about.
std::string compact(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace

struct SceneDocument::State {
  std::string path;
  std::string original;  // the text as read (or as last saved): the layout text() keeps
  Json root;
  Json saved;            // root as read or last saved, for modified()
  struct Step {
    Json before;
    std::string label;
  };
  std::vector<Step> undo, redo;
  std::optional<Scene> scene;
  std::optional<std::string> problem;

  // Parses root as the loader would parse the file, keeping the scene or the problem.
  void validate() {
    try {
      scene = parseScene(compact(root), path);
      problem.reset();
    } catch (const InputError& e) {
      scene.reset();
      problem = e.what();
    }
  }
};

SceneDocument::SceneDocument(std::unique_ptr<State> state) : state_(std::move(state)) {}
SceneDocument::~SceneDocument() = default;
SceneDocument::SceneDocument(const SceneDocument& other) : state_(std::make_unique<State>(*other.state_)) {}
SceneDocument& SceneDocument::operator=(const SceneDocument& other) {
  if (this != &other) state_ = std::make_unique<State>(*other.state_);
  return *this;
}
SceneDocument::SceneDocument(SceneDocument&&) noexcept = default;
SceneDocument& SceneDocument::operator=(SceneDocument&&) noexcept = default;

SceneDocument SceneDocument::load(const std::string& path) { return fromText(readSceneFile(path), path); }

SceneDocument SceneDocument::fromText(const std::string& text, const std::string& path) {
  auto state = std::make_unique<State>();
  state->path = path;
  state->original = text;
  state->root = Json::parse(text, nullptr, false);
  if (state->root.is_discarded() || !state->root.is_object() || text.find('\0') != std::string::npos) {
    // The loader's own message says what is wrong (malformed JSON, a number too large).
    parseScene(text, path);
    throw InputError(path + ": must be a JSON object (a scene: docs/scene-format.md)");
  }
  state->saved = state->root;
  state->validate();
  return SceneDocument(std::move(state));
}

const std::string& SceneDocument::path() const { return state_->path; }

const Scene& SceneDocument::scene() const {
  if (!state_->scene) throw InputError(*state_->problem);
  return *state_->scene;
}

const std::optional<std::string>& SceneDocument::problem() const { return state_->problem; }

double SceneDocument::parameter(const std::string& name) const { return parameterIn(state_->root, ib::parameter(name)); }

void SceneDocument::setFromText(const std::string& assignment) {
  const size_t equals = assignment.find('=');
  const std::string where = "--set " + inQuotes(assignment);
  if (equals == std::string::npos || equals == 0) throw InputError(where + ": expected NAME=VALUE, e.g. tau=1e-4");
  const std::string name = assignment.substr(0, equals);
  try {
    const ParameterSpec& spec = ib::parameter(name);
    if (spec.field.empty())
      throw InputError(inQuotes(name) + " is the player's own (a slider in `inbetween play`), not a field of the scene");
    apply(edit::SetParameter{spec.name, parseParameterText(spec, assignment.substr(equals + 1), where)});
  } catch (const InputError& e) {
    const std::string message = e.what();
    throw InputError(message.rfind(where, 0) == 0 ? message : where + ": " + message);
  }
}

void SceneDocument::apply(const edit::SceneEdit& change) { applyAll({change}); }

void SceneDocument::applyAll(const std::vector<edit::SceneEdit>& changes) {
  if (changes.empty()) return;
  Json edited = state_->root;
  for (const edit::SceneEdit& change : changes) {
    try {
      applyEdit(edited, change);
    } catch (const nlohmann::json::exception& e) {  // a part of the file is not of the type the edit needs
      throw InputError(state_->path + ": cannot " + edit::describe(change) + ": the file's JSON is not as a scene's (" +
                       e.what() + "); fix the file first");
    }
  }
  if (edited == state_->root) return;
  std::string label = edit::describe(changes.front());
  if (changes.size() > 1) label += " and " + std::to_string(changes.size() - 1) + " more";
  state_->undo.push_back({std::move(state_->root), label});
  state_->redo.clear();
  state_->root = std::move(edited);
  state_->validate();
}

bool SceneDocument::canUndo() const { return !state_->undo.empty(); }
bool SceneDocument::canRedo() const { return !state_->redo.empty(); }
std::string SceneDocument::undoLabel() const { return state_->undo.empty() ? "" : state_->undo.back().label; }
std::string SceneDocument::redoLabel() const { return state_->redo.empty() ? "" : state_->redo.back().label; }

void SceneDocument::undo() {
  if (state_->undo.empty()) return;
  State::Step step = std::move(state_->undo.back());
  state_->undo.pop_back();
  state_->redo.push_back({std::move(state_->root), step.label});
  state_->root = std::move(step.before);
  state_->validate();
}

void SceneDocument::redo() {
  if (state_->redo.empty()) return;
  State::Step step = std::move(state_->redo.back());
  state_->redo.pop_back();
  state_->undo.push_back({std::move(state_->root), step.label});
  state_->root = std::move(step.before);
  state_->validate();
}

std::string SceneDocument::text() const { return rewriteJson(state_->original, state_->root); }

std::string SceneDocument::json() const { return compact(state_->root); }

void SceneDocument::save() {
  const std::string written = text();
  writeFileAtomically(state_->path, written);
  state_->original = written;
  state_->saved = state_->root;
}

bool SceneDocument::modified() const { return state_->root != state_->saved; }

}  // namespace ib
