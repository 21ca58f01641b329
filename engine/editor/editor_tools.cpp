// EditorView's tools on a key's view: what a press, a drag and a release do with the Features,
// Cut, Interior and Stiffness tools (editor/editor_view.h). Each finished gesture is one edit of
// the document.
#include "editor/editor_view.h"

#include "core/error.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ib::editor {

namespace {

constexpr double kGrabScreenPixels = 9;  // window px: a press this close to a mark takes it

const char* const kCutKinds[] = {"notch", "split", "slit"};

}  // namespace

void EditorView::featureInput(int key, const Eigen::Vector2d& p, bool pressed, bool held, bool released) {
  const KeyMarks& marks = session_.marks().keys[static_cast<size_t>(key)];
  const double unit = 1 / pixelsPerUnit(key);  // drawing px per window px
  if (pressed) {
    // On a feature: select it and start dragging it along the outline.
    std::string nearest;
    double best = kGrabScreenPixels * unit;
    for (const auto& [name, at] : marks.features)
      if ((at - p).norm() <= best) best = (at - p).norm(), nearest = name;
    if (!nearest.empty()) {
      selectedKey_ = key;
      selected_ = nearest;
      selectedInterior_ = false;
      dragging_ = true;
      dragAt_ = marks.features.at(nearest);
      std::snprintf(renameBuffer_.data(), renameBuffer_.size(), "%s", nearest.c_str());
      return;
    }
    const std::optional<Eigen::Vector2d> on = session_.snap(key, p, tools_.snapScreenPixels * unit);
    if (!on) {
      report("click on key `" + marks.name + "`'s outline (within " + std::to_string(int(tools_.snapScreenPixels)) +
                 " screen px) to place a feature there",
             true);
      return;
    }
    // The feature this key still lacks comes first; else a new one.
    std::string name;
    for (const MissingFeature& m : missingFeatures(session_.marks(), -1))
      if (m.key == marks.name && !m.interior) {
        name = m.feature;
        break;
      }
    if (name.empty()) name = session_.freshName("f");
    run(edit::SetFeature{marks.name, name, *on});
    selectedKey_ = key;
    selected_ = name;
    selectedInterior_ = false;
    lastEditedKey_ = key;
    std::snprintf(renameBuffer_.data(), renameBuffer_.size(), "%s", name.c_str());
    return;
  }
  if (dragging_ && held) {
    if (const auto on = session_.snap(key, p, INFINITY)) dragAt_ = *on;
    return;
  }
  if (dragging_ && released) {
    dragging_ = false;
    const auto it = marks.features.find(selected_);
    if (it != marks.features.end() && (it->second - dragAt_).norm() > 1e-6) {
      run(edit::SetFeature{marks.name, selected_, dragAt_});
      lastEditedKey_ = key;
    }
  }
}

void EditorView::cutInput(int key, const Eigen::Vector2d& p, bool pressed, bool doubleClicked) {
  if (!pressed && !doubleClicked) return;
  if (cutKey_ != key) {
    cutKey_ = key;
    cutPoints_.clear();
  }
  if (doubleClicked) {
    finishCut();
    return;
  }
  cutPoints_.push_back(p);
}

void EditorView::finishCut() {
  if (cutKey_ < 0 || cutKey_ >= session_.keyCount()) return;
  // A double click's second press added the same point again.
  while (cutPoints_.size() >= 2 && (cutPoints_.back() - cutPoints_[cutPoints_.size() - 2]).norm() < 1e-9) cutPoints_.pop_back();
  if (cutPoints_.size() < 2) {
    report("a cut needs two points or more: click them in the key, then double-click or press Enter", true);
    return;
  }
  const std::string key = session_.marks().keys[static_cast<size_t>(cutKey_)].name;
  const std::string name = session_.freshName("cut");
  run(edit::AddCut{key, name, kCutKinds[tools_.cutKind], cutPoints_});
  lastEditedKey_ = cutKey_;
  cutPoints_.clear();
  cutKey_ = -1;
}

void EditorView::interiorInput(int key, const Eigen::Vector2d& p, bool pressed, bool released) {
  const KeyMarks& marks = session_.marks().keys[static_cast<size_t>(key)];
  const double unit = 1 / pixelsPerUnit(key);
  if (pressed) {
    selectedKey_ = key;
    selectedInterior_ = true;
    dragging_ = true;
    draggingRadius_ = false;
    dragAt_ = p;
    selected_.clear();
    for (const auto& [name, at] : marks.interior)
      if ((at - p).norm() <= kGrabScreenPixels * unit) selected_ = name, dragAt_ = at;
    // Not on a point: on a disc's rim, its radius is dragged.
    for (const auto& [name, at] : marks.interior) {
      const auto r = marks.radii.find(name);
      if (selected_.empty() && r != marks.radii.end() && std::abs((at - p).norm() - r->second) <= kGrabScreenPixels * unit)
        selected_ = name, dragAt_ = at, draggingRadius_ = true;
    }
    if (selected_.empty()) {
      for (const MissingFeature& m : missingFeatures(session_.marks(), -1))
        if (m.key == marks.name && m.interior) {
          selected_ = m.feature;
          break;
        }
      if (selected_.empty()) selected_ = session_.freshName("detail");
      hover_ = p;
    }
    std::snprintf(renameBuffer_.data(), renameBuffer_.size(), "%s", selected_.c_str());
    return;
  }
  if (!dragging_ || !released) return;
  dragging_ = false;
  if (draggingRadius_) {  // the same radius in every key (edit::SetInteriorRadius)
    draggingRadius_ = false;
    const double radius = std::clamp((p - dragAt_).norm(), kMinInteriorRadius, kMaxInteriorRadius);
    const auto r = marks.radii.find(selected_);
    if (r != marks.radii.end() && std::abs(radius - r->second) * pixelsPerUnit(key) > 1) run(edit::SetInteriorRadius{selected_, radius});
    return;
  }
  const auto existing = marks.interior.find(selected_);
  if (existing != marks.interior.end()) {  // moved: the radius stays
    const double moved = (p - dragAt_).norm();
    if (moved * pixelsPerUnit(key) > 2) {
      const auto r = marks.radii.find(selected_);
      run(edit::SetInteriorFeature{marks.name, selected_, existing->second + (p - dragAt_),
                                   r == marks.radii.end() ? std::nullopt : std::optional<double>(r->second)});
    }
    return;
  }
  // New: the press is the point, the drag the radius (none for a click).
  const double radius = (p - dragAt_).norm();
  std::optional<double> r;
  if (radius * pixelsPerUnit(key) > 3) r = std::clamp(radius, kMinInteriorRadius, kMaxInteriorRadius);
  // The same feature in every key has one radius: a later key takes the first's.
  for (const KeyMarks& k : session_.marks().keys)
    if (k.radii.count(selected_)) r = k.radii.at(selected_);
  run(edit::SetInteriorFeature{marks.name, selected_, dragAt_, r});
  lastEditedKey_ = key;
}

void EditorView::paintInput(int key, const Eigen::Vector2d& p, bool pressed, bool held, bool released) {
  const DocumentMarks& marks = session_.marks();
  const std::string name = marks.keys[static_cast<size_t>(key)].name;
  if (pressed && name != marks.reference) {
    report("paint stiffness on the reference key `" + marks.reference + "`: its triangles carry kappa", true);
    return;
  }
  if (pressed && tools_.erase) {
    for (const StrokeMark& s : marks.strokes)
      for (const Eigen::Vector2d& q : s.points)
        if (s.key == name && (q - p).norm() <= s.radius + tools_.brushRadius) {
          run(edit::RemoveStiffness{s.name});
          return;
        }
    return;
  }
  if (tools_.erase) return;
  if (pressed) {
    paintKey_ = key;
    paintPoints_ = {p};
    return;
  }
  if (paintKey_ == key && held) {
    if ((p - paintPoints_.back()).norm() >= 0.5 * tools_.brushRadius) paintPoints_.push_back(p);
    return;
  }
  if (paintKey_ == key && released) {
    if ((p - paintPoints_.back()).norm() > 1e-9) paintPoints_.push_back(p);
    run(edit::AddStiffnessStroke{session_.freshName("stroke"), name, paintPoints_, tools_.brushRadius, tools_.brushKappa});
    paintKey_ = -1;
    paintPoints_.clear();
  }
}

}  // namespace ib::editor
