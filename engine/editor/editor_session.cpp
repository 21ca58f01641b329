#include "editor/editor_session.h"

#include "core/error.h"

#include <filesystem>
#include <set>

namespace ib::editor {

namespace fs = std::filesystem;

EditorSession::EditorSession(SceneDocument document)
    : document_(std::move(document)), marks_(marksOf(document_.json())), tracer_(document_.scene()) {
  for (const KeySpec& key : document_.scene().keys) openedKeys_[key.name] = {key.drawing, key.holes};
  changed();
  generation_ = 0;
}

void EditorSession::changed() {
  marks_ = marksOf(document_.json());
  const size_t m = marks_.keys.size();
  outlines_.resize(m);
  outlineErrors_.resize(m);
  tracedDrawing_.resize(m);
  for (size_t k = 0; k < m; ++k)
    if (tracedDrawing_[k] != marks_.keys[k].name + "\n" + marks_.keys[k].drawing) {
      outlines_[k].reset();  // a key added, removed, moved or given another drawing
      outlineErrors_[k].clear();
    }
  arcsCurrent_ = false;
  ++generation_;
}

std::string EditorSession::drawingPath(int key) const {
  const std::string& drawing = marks_.keys.at(static_cast<size_t>(key)).drawing;
  if (fs::path(drawing).is_absolute()) return drawing;
  return (fs::path(document_.path()).parent_path() / drawing).string();
}

const std::vector<Outline>& EditorSession::outlines(int key) {
  auto& cached = outlines_.at(static_cast<size_t>(key));
  if (!cached) {
    const KeyMarks& k = marks_.keys[static_cast<size_t>(key)];
    cached.emplace();
    tracedDrawing_[static_cast<size_t>(key)] = k.name + "\n" + k.drawing;
    try {
      // A key of the scene as opened, with its drawing, keeps its hole points; others are traced
      // plainly. Registered again every time: a drawing swapped and swapped back is traced anew.
      const auto opened = openedKeys_.find(k.name);
      const std::string path = fs::path(drawingPath(key)).lexically_normal().string();
      if (opened != openedKeys_.end() && fs::path(opened->second.first).lexically_normal().string() == path)
        tracer_.add(k.name, path, opened->second.second);
      else
        tracer_.add(k.name, path);
      *cached = *tracer_.of(k.name);
    } catch (const InputError& e) {
      outlineErrors_[static_cast<size_t>(key)] = e.what();
    }
  }
  return *cached;
}

std::string EditorSession::outlineError(int key) {
  outlines(key);
  return outlineErrors_.at(static_cast<size_t>(key));
}

const std::vector<OutlineArc>& EditorSession::arcs(int key) {
  orderProblem();
  return arcs_.at(static_cast<size_t>(key));
}

const std::string& EditorSession::orderProblem() {
  if (!arcsCurrent_) {
    std::map<std::pair<std::string, std::string>, int> colours;
    arcs_.assign(marks_.keys.size(), {});
    // The reference key first, so its arcs take the first colours.
    std::vector<int> order;
    const int reference = std::max(0, marks_.keyIndex(marks_.reference));
    if (!marks_.keys.empty()) order.push_back(reference);
    for (int k = 0; k < keyCount(); ++k)
      if (k != reference) order.push_back(k);
    for (int k : order) arcs_[static_cast<size_t>(k)] = outlineArcs(outlines(k), marks_.keys[static_cast<size_t>(k)].features, colours);
    orderProblem_ = editor::orderProblems(marks_, arcs_);
    arcsCurrent_ = true;
  }
  return orderProblem_;
}

std::optional<Eigen::Vector2d> EditorSession::snap(int key, const Eigen::Vector2d& p, double within) {
  const std::vector<Outline>& o = outlines(key);
  if (o.empty()) return std::nullopt;
  const Eigen::Vector2d on = nearestOnOutlines(o, p);
  if ((on - p).norm() > within) return std::nullopt;
  return on;
}

void EditorSession::apply(const edit::SceneEdit& edit) {
  document_.apply(edit);
  changed();
}

void EditorSession::applyAll(const std::vector<edit::SceneEdit>& edits) {
  document_.applyAll(edits);
  changed();
}

void EditorSession::undo() {
  if (!document_.canUndo()) return;
  document_.undo();
  changed();
}

void EditorSession::redo() {
  if (!document_.canRedo()) return;
  document_.redo();
  changed();
}

void EditorSession::save() { document_.save(); }

std::string EditorSession::freshName(const std::string& prefix) const {
  std::set<std::string> used;
  for (const KeyMarks& k : marks_.keys) {
    for (const auto& [name, p] : k.features) used.insert(name);
    for (const auto& [name, p] : k.interior) used.insert(name);
    for (const CutMark& c : k.cuts) used.insert(c.name);
  }
  for (const StrokeMark& s : marks_.strokes) used.insert(s.name);
  for (int i = 1;; ++i)
    if (!used.count(prefix + std::to_string(i))) return prefix + std::to_string(i);
}

std::optional<MissingFeature> EditorSession::nextMissing(int after) const {
  const std::vector<MissingFeature> missing = missingFeatures(marks_, after);
  if (missing.empty()) return std::nullopt;
  return missing.front();
}

}  // namespace ib::editor
