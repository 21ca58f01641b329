// A scene file as a document: its JSON, the typed edits that change it (scene/scene_edits.h)
// with undo and redo, its validation into a Scene, and a writer that keeps the file's layout, so
// one edit is a small diff (core/json_layout.h). The player's Save, the editor and `--set` all
// change scenes through it.
//
// A document may be mid-edit: an edit that leaves the scene invalid (a feature placed in one key
// only, so far) is applied, and problem() names the key and field as loading the file would.
// An edit that cannot apply at all (a key that does not exist, a name taken, a value out of its
// range) throws InputError and changes nothing.
#pragma once

#include "scene/scene.h"
#include "scene/scene_edits.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ib {

class SceneDocument {
 public:
  // Reads a scene file. InputError naming the file when it cannot be read or is not a JSON object
  // (a scene that does not validate opens: see problem()).
  static SceneDocument load(const std::string& path);
  // The same from text; `path` names the file in messages and resolves the drawings.
  static SceneDocument fromText(const std::string& text, const std::string& path);
  ~SceneDocument();
  SceneDocument(const SceneDocument&);
  SceneDocument& operator=(const SceneDocument&);
  SceneDocument(SceneDocument&&) noexcept;
  SceneDocument& operator=(SceneDocument&&) noexcept;

  const std::string& path() const;
  // The validated scene; throws the InputError problem() holds when the document is not a valid scene.
  const Scene& scene() const;
  // Why the document is not a valid scene (the loader's message, naming file, key and field), or none.
  const std::optional<std::string>& problem() const;

  // A parameter of the table (scene/parameters.h): the document's value, or its default when the
  // file does not say. InputError for an unknown name (with "did you mean").
  double parameter(const std::string& name) const;
  // Sets a parameter from text as --set gives it (`NAME=VALUE`): InputError naming the text.
  void setFromText(const std::string& assignment);

  // Applies an edit (see the header comment), recorded for undo; the redo list is cleared.
  void apply(const edit::SceneEdit& edit);
  // Applies edits in order as one: a single undo step (labelled with the first's description and
  // how many follow), and none of them when one fails (its InputError).
  void applyAll(const std::vector<edit::SceneEdit>& edits);
  bool canUndo() const;
  bool canRedo() const;
  std::string undoLabel() const;  // describe() of the edit undo() takes back; empty when none
  std::string redoLabel() const;
  void undo();  // no-op when there is nothing to undo
  void redo();

  // The document as text in the layout of the file it was read from.
  std::string text() const;
  // The document's JSON without the file's layout (compact); text() parses to the same JSON.
  std::string json() const;
  // Writes text() to the file atomically (core/atomic_file.h); InputError naming it on failure.
  void save();
  // Edits since the document was read or last saved.
  bool modified() const;

  struct State;  // scene_document.cpp: the JSON, the history, the validation

 private:
  explicit SceneDocument(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace ib
