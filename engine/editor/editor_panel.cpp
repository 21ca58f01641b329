// EditorView's Edit tab (tools, selection, what to place next, keys, undo / redo / save) and the
// unsaved-changes dialog.
#include "editor/editor_view.h"

#include "core/error.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ib::editor {

namespace {

constexpr float kStateLines = 5;  // the height of the Edit tab's state box, in lines of text
const char* const kToolNames[] = {"Features", "Cut", "Interior", "Stiffness"};
const char* const kToolKeys[] = {"Q", "C", "D", "B"};
const char* const kToolHelp[] = {
    "Click on a key's outline to place a feature; drag one along the outline. Delete removes the selected one from its key, Shift+Delete from every key.",
    "Click the cut's points inside a key, double-click or press Enter to end it (Esc cancels).",
    "Press at a detail inside the shape; drag to give it a disc that moves with it as one piece.",
    "Paint stiffness on the reference key: kappa above 1 keeps a part rigid, below 1 lets it give."};

}  // namespace

void EditorView::panel() {
  const SceneDocument& doc = session_.document();
  int tool = static_cast<int>(tools_.tool);
  for (int t = 0; t < 4; ++t) {
    if (t > 0) ImGui::SameLine();
    if (ImGui::RadioButton(kToolNames[t], tool == t)) tools_.tool = static_cast<Tool>(t);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kToolKeys[t]);
  }
  ImGui::TextWrapped("%s", kToolHelp[static_cast<int>(tools_.tool)]);
  if (tools_.tool == Tool::kCut) ImGui::Combo("kind", &tools_.cutKind, "notch\0split\0slit\0");
  if (tools_.tool == Tool::kPaint) {
    float radius = static_cast<float>(tools_.brushRadius), kappa = static_cast<float>(tools_.brushKappa);
    if (ImGui::SliderFloat("radius px", &radius, 1, 200, "%.0f", ImGuiSliderFlags_Logarithmic)) tools_.brushRadius = radius;
    if (ImGui::SliderFloat("kappa", &kappa, 0.1f, 10, "%.2f", ImGuiSliderFlags_Logarithmic)) tools_.brushKappa = kappa;
    ImGui::Checkbox("erase (click a stroke)", &tools_.erase);
  }
  if (tools_.tool == Tool::kFeature) {
    float snap = static_cast<float>(tools_.snapScreenPixels);
    if (ImGui::SliderFloat("snap (screen px)", &snap, 2, 40, "%.0f")) tools_.snapScreenPixels = snap;
  }

  ImGui::Separator();
  // What to do next, and what is wrong, in words, in a box of fixed height: the controls below
  // stay where they are while rebuilds start and end and messages come and go under the pointer.
  ImGui::BeginChild("##state", ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * kStateLines), false);
  if (player_.reloader().busy())
    ImGui::Text("rebuilding: %s (%.0f%%)", player_.reloader().stage().c_str(), 100 * player_.reloader().progress());
  else if (latencyMs_ >= 0)
    ImGui::TextDisabled("last edit to new frame: %.0f ms", latencyMs_);
  else
    ImGui::TextDisabled("built");
  if (const std::optional<MissingFeature> next = session_.nextMissing(lastEditedKey_)) {
    ImGui::TextColored(ImVec4(1, 0.82f, 0, 1), "place `%s` in key `%s`%s", next->feature.c_str(), next->key.c_str(),
                       next->interior ? " (Interior tool)" : "");
    // The rest still to place (a cut's features, a feature added to one key of several).
    const std::vector<MissingFeature> all = missingFeatures(session_.marks(), lastEditedKey_);
    std::string rest;
    for (size_t i = 1; i < all.size() && i <= 6; ++i) rest += (i > 1 ? ", " : "then ") + all[i].feature + " in " + all[i].key;
    if (all.size() > 7) rest += ", ...";
    if (!rest.empty()) ImGui::TextDisabled("%s", rest.c_str());
  }
  const auto wrapped = [](const ImVec4& colour, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
  };
  const ImVec4 red(1, 0.35f, 0.35f, 1);
  if (!session_.orderProblem().empty()) wrapped(red, session_.orderProblem());
  else if (doc.problem() && !session_.nextMissing(lastEditedKey_)) wrapped(red, *doc.problem());
  if (!buildError_.empty()) wrapped(red, "build: " + buildError_);
  if (!status_.empty()) wrapped(statusError_ ? red : ImVec4(0.6f, 1, 0.6f, 1), status_);
  ImGui::EndChild();

  // The selection.
  if (selectedKey_ >= 0 && selectedKey_ < session_.keyCount() && !selected_.empty()) {
    ImGui::Separator();
    const std::string key = session_.marks().keys[static_cast<size_t>(selectedKey_)].name;
    ImGui::Text("%s `%s` in key `%s`", selectedInterior_ ? "interior feature" : "feature", selected_.c_str(), key.c_str());
    // A click in a name's field selects it: typing replaces it.
    ImGui::InputText("##name", renameBuffer_.data(), renameBuffer_.size(), ImGuiInputTextFlags_AutoSelectAll);
    drawnAt("name");
    ImGui::SameLine();
    const bool rename = ImGui::Button("Rename");
    drawnAt("Rename");
    if (rename && renameBuffer_[0] != '\0' && selected_ != renameBuffer_.data()) {
      const std::string to = renameBuffer_.data();
      if (selectedInterior_) run(edit::RenameInteriorFeature{selected_, to});
      else run(edit::RenameFeature{selected_, to});
      if (status_.empty() || !statusError_) selected_ = to;
    }
    if (ImGui::Button("Delete in this key")) {
      if (selectedInterior_) run(edit::RemoveInteriorFeature{selected_, key});
      else run(edit::RemoveFeature{selected_, key});
      selected_.clear();
    }
    ImGui::SameLine();
    if (ImGui::Button("Delete in every key")) {
      if (selectedInterior_) run(edit::RemoveInteriorFeature{selected_, ""});
      else run(edit::RemoveFeature{selected_, ""});
      selected_.clear();
    }
  }
  suggestionsPanel();
  cutsPanel();
  keysPanel();
  markPanel();

  ImGui::Separator();
  // Whether each can act, read once: the click changes it before the disabled scope ends.
  const bool canUndo = doc.canUndo(), canRedo = doc.canRedo();
  const std::string undoLabel = doc.undoLabel(), redoLabel = doc.redoLabel();
  ImGui::BeginDisabled(!canUndo);
  if (ImGui::Button("Undo")) shortcut(90, true, false);
  drawnAt("Undo");
  ImGui::EndDisabled();
  if (canUndo && ImGui::IsItemHovered()) ImGui::SetTooltip("Ctrl+Z: %s", undoLabel.c_str());
  ImGui::SameLine();
  ImGui::BeginDisabled(!canRedo);
  if (ImGui::Button("Redo")) shortcut(90, true, true);
  drawnAt("Redo");
  ImGui::EndDisabled();
  if (canRedo && ImGui::IsItemHovered()) ImGui::SetTooltip("Ctrl+Shift+Z: %s", redoLabel.c_str());
  ImGui::SameLine();
  if (ImGui::Button(doc.modified() ? "Save *" : "Save")) shortcut(83, true, false);
}

void EditorView::suggestionsPanel() {
  ImGui::Separator();
  if (ImGui::Button("Suggest features")) suggest();
  drawnAt("Suggest features");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("propose features: where the shape matching pairs the outlines' corners between the features placed, "
                      "or, before any, where every key's outline has a corresponding corner");
  if (suggestions_.empty()) return;
  ImGui::SameLine();
  const bool all = ImGui::Button("Accept all");
  drawnAt("Accept all");
  if (all) {
    acceptAll();
    return;
  }
  // Each row's label, and the column the buttons start at: past the widest label.
  std::vector<std::string> labels;
  float column = 0;
  for (size_t i = 0; i < suggestions_.size(); ++i) {
    char label[64];
    if (suggestions_[i].confidence >= 0)
      std::snprintf(label, sizeof label, "?%zu  sure %.2f, moved %.0f px", i + 1, suggestions_[i].confidence, suggestions_[i].moved);
    else
      std::snprintf(label, sizeof label, "?%zu  corner, %.0f deg", i + 1, suggestions_[i].turn * 180 / 3.14159265358979);
    labels.emplace_back(label);
    column = std::max(column, ImGui::CalcTextSize(label).x);
  }
  column += ImGui::GetCursorPosX() + ImGui::GetStyle().ItemSpacing.x * 2;
  for (size_t i = 0; i < suggestions_.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    ImGui::TextUnformatted(labels[i].c_str());
    ImGui::SameLine(column);
    if (ImGui::SmallButton("accept")) {
      accept(i);
      ImGui::PopID();
      return;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("drop")) {
      suggestions_.erase(suggestions_.begin() + static_cast<std::ptrdiff_t>(i));
      ImGui::PopID();
      return;
    }
    ImGui::PopID();
  }
}

void EditorView::cutsPanel() {
  // Every cut once (a cut closed in several keys is one), with its kind, a new name and remove.
  std::vector<std::pair<std::string, std::string>> cuts;  // name, kind
  for (const KeyMarks& k : session_.marks().keys)
    for (const CutMark& c : k.cuts)
      if (std::find_if(cuts.begin(), cuts.end(), [&](const auto& n) { return n.first == c.name; }) == cuts.end())
        cuts.push_back({c.name, c.kind});
  if (cuts.empty()) return;
  ImGui::Separator();
  ImGui::TextDisabled("Cuts (renaming one renames the features it creates)");
  cutNames_.resize(cuts.size());
  for (size_t i = 0; i < cuts.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    auto& [filledFrom, buffer] = cutNames_[i];
    if (filledFrom != cuts[i].first) {  // a new list (a cut added, renamed, undone): the field shows the name
      filledFrom = cuts[i].first;
      std::snprintf(buffer.data(), buffer.size(), "%s", filledFrom.c_str());
    }
    ImGui::SetNextItemWidth(120);
    ImGui::InputText("##cut", buffer.data(), buffer.size(), ImGuiInputTextFlags_AutoSelectAll);
    drawnAt("cut " + std::to_string(i));
    ImGui::SameLine();
    ImGui::TextDisabled("%s", cuts[i].second.c_str());
    ImGui::SameLine(200);
    const bool rename = ImGui::SmallButton("rename");
    drawnAt("cut " + std::to_string(i) + " rename");
    if (rename && cuts[i].first != buffer.data()) run(edit::RenameCut{cuts[i].first, buffer.data()});
    ImGui::SameLine();
    if (ImGui::SmallButton("remove")) {
      run(edit::RemoveCut{cuts[i].first, ""});
      cutNames_.clear();
      ImGui::PopID();
      return;
    }
    ImGui::PopID();
  }
}

void EditorView::keysPanel() {
  ImGui::Separator();
  ImGui::TextDisabled("Keys (drop PNG files on the window to add more)");
  const DocumentMarks& marks = session_.marks();
  for (int k = 0; k < session_.keyCount(); ++k) {
    const std::string name = marks.keys[static_cast<size_t>(k)].name;
    ImGui::PushID(k);
    if (ImGui::RadioButton("##reference", name == marks.reference) && name != marks.reference) run(edit::SetReference{name});
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the reference key: its drawing is triangulated, stiffness is painted on it");
    ImGui::SameLine();
    if (ImGui::Selectable((std::to_string(k) + "  " + name).c_str(), selectedKey_ == k, 0, ImVec2(140, 0))) {
      selectedKey_ = k;
      focus(k);
    }
    drawnAt("key " + std::to_string(k));
    ImGui::SameLine(200);
    const bool first = k == 0, last = k + 1 == session_.keyCount();  // read once: a move changes them
    ImGui::BeginDisabled(first);
    if (ImGui::ArrowButton("up", ImGuiDir_Left)) run(edit::MoveKey{name, k - 1});
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(last);
    if (ImGui::ArrowButton("down", ImGuiDir_Right)) run(edit::MoveKey{name, k + 1});
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(session_.keyCount() <= 1);  // a scene keeps at least one key
    if (ImGui::SmallButton("remove")) run(edit::RemoveKey{name});
    ImGui::EndDisabled();
    ImGui::PopID();
  }
  ImGui::InputTextWithHint("##drawing", "drawing.png", addKeyBuffer_.data(), addKeyBuffer_.size());
  ImGui::SameLine();
  if (ImGui::Button("Add key") && addKeyBuffer_[0] != '\0') {
    dropped({addKeyBuffer_.data()});
    addKeyBuffer_[0] = '\0';
  }
  if (selectedKey_ >= 0 && selectedKey_ < session_.keyCount()) {
    const std::string name = marks.keys[static_cast<size_t>(selectedKey_)].name;
    ImGui::InputTextWithHint("##swap", marks.keys[static_cast<size_t>(selectedKey_)].drawing.c_str(), drawingBuffer_.data(),
                             drawingBuffer_.size());
    ImGui::SameLine();
    if (ImGui::Button("Swap drawing") && drawingBuffer_[0] != '\0') {
      run(edit::SetKeyDrawing{name, drawingBuffer_.data()});
      drawingBuffer_[0] = '\0';
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("draw key `%s` from another PNG (relative to the scene file)", name.c_str());
  }
}

void EditorView::markPanel() {
  const Timeline& timeline = player_.scene().scene.timeline;
  if (selectedMark_ < 0 || selectedMark_ >= static_cast<int>(timeline.marks().size())) return;
  ImGui::Separator();
  const TimelineMark& mark = timeline.marks()[static_cast<size_t>(selectedMark_)];
  ImGui::Text("mark %d at %.3f s", selectedMark_ + 1, mark.time);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("drag its diamond on the timeline to move it in time");
  // Its key.
  const DocumentMarks& marks = session_.marks();
  int key = marks.keyIndex(mark.label);
  std::string names;
  for (const KeyMarks& k : marks.keys) names += k.name + '\0';
  ImGui::SetNextItemWidth(160);
  if (ImGui::Combo("key", &key, names.c_str()) && key >= 0) run(edit::SetMarkKey{selectedMark_, marks.keys[static_cast<size_t>(key)].name});
  // Its ease into the next mark.
  static const char* const kEases[] = {"linear", "ease-in", "ease-out", "ease-in-out", "hold"};
  ImGui::SetNextItemWidth(160);
  const std::string current = selectedMark_ < static_cast<int>(marks.markEases.size()) ? marks.markEases[static_cast<size_t>(selectedMark_)] : "";
  if (ImGui::BeginCombo("ease", current.c_str())) {
    for (const char* ease : kEases)
      if (ImGui::Selectable(ease)) run(edit::SetMarkEase{selectedMark_, std::string("\"") + ease + "\""});
    ImGui::EndCombo();
  }
}

bool EditorView::closeDialog() {
  if (closeAsked_) {
    ImGui::OpenPopup("Unsaved changes");
    closeAsked_ = false;
  }
  bool close = false;
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s has unsaved changes.", session_.document().path().c_str());
    if (ImGui::Button("Save and close")) {
      try {
        session_.save();
        close = true;
      } catch (const InputError& e) {
        report(e.what(), true);
      }
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Close without saving")) {
      close = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  return close;
}

void EditorView::drawnAt(const std::string& control) {
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  buttons_[control] = {lo.x, lo.y, hi.x, hi.y};
}

}  // namespace ib::editor
