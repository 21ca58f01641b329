// The editor's model, CPU only: the scene document (every edit undoable, saved in the file's
// layout), what each key shows (marks, traced outlines, coloured arcs), the features still to
// place, and a generation that counts changes, from which the window starts a background rebuild.
// The window's edits are the document's typed edits (scene/scene_edits.h), the same ones
// `inbetween edit --apply` makes; features snap onto the traced outline as it snaps them.
#pragma once

#include "editor/editor_marks.h"
#include "pipeline/key_outlines.h"
#include "scene/scene_document.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ib::editor {

class EditorSession {
 public:
  // The document must be a valid scene (it opens in the player first).
  explicit EditorSession(SceneDocument document);

  const SceneDocument& document() const { return document_; }
  const DocumentMarks& marks() const { return marks_; }
  int keyCount() const { return static_cast<int>(marks_.keys.size()); }
  // Increments with every change of the document (edit, undo, redo).
  int generation() const { return generation_; }

  // Key k's traced outlines (empty when its drawing cannot be traced: see outlineError).
  const std::vector<Outline>& outlines(int key);
  std::string outlineError(int key);
  // Key k's outline arcs, coloured by the pair of features they join (editor_marks.h).
  const std::vector<OutlineArc>& arcs(int key);
  // Why features are in a different order in two keys, naming them; empty when they agree.
  const std::string& orderProblem();
  // The drawing file of key k, resolved against the scene's folder.
  std::string drawingPath(int key) const;

  // The nearest outline point of key k to p (drawing pixels) when it is within `within` px, else none.
  std::optional<Eigen::Vector2d> snap(int key, const Eigen::Vector2d& p, double within);

  // Applies an edit. InputError (the document's message) when it cannot apply: nothing changes.
  void apply(const edit::SceneEdit& edit);
  void applyAll(const std::vector<edit::SceneEdit>& edits);  // as one undo step, all or none
  void undo();
  void redo();
  void save();  // atomically, in the file's layout; InputError naming the file

  // A name not used by any feature, interior feature, cut or stroke: PREFIX1, PREFIX2, ...
  std::string freshName(const std::string& prefix) const;
  // What to place next: the first feature a key lacks, after key `after` (the one just edited).
  std::optional<MissingFeature> nextMissing(int after) const;

 private:
  void changed();

  SceneDocument document_;
  DocumentMarks marks_;
  KeyOutlines tracer_;
  std::map<std::string, std::pair<std::string, Polyline>> openedKeys_;  // key -> drawing path, hole points, as opened
  std::vector<std::optional<std::vector<Outline>>> outlines_;  // [key]: traced, cached per drawing
  std::vector<std::string> outlineErrors_;
  std::vector<std::string> tracedDrawing_;  // [key]: the drawing its outline was traced from
  std::vector<std::vector<OutlineArc>> arcs_;
  std::string orderProblem_;
  bool arcsCurrent_ = false;
  int generation_ = 0;
};

}  // namespace ib::editor
