// The parameters: a slider (log-scaled where the table asks; Ctrl+click types any value the scene
// file takes), a toggle or a choice per live parameter (scene/parameters.h), each with its default
// and a reset; the solver's and the dynamics' in two groups. A change goes
// to the solve worker in the session's next update.
#include "player/player_ui.h"

#include "core/error.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace ib::play {

namespace {

bool dynamicsControl(const Control& c) { return c.spec->name == "dynamics" || c.spec->field.rfind("dynamics.", 0) == 0; }

// The value as the table writes it, with its unit.
std::string shown(const ParameterSpec& spec, double value) {
  return formatParameterValue(spec, value) + (spec.unit.empty() ? "" : " " + spec.unit);
}

// Where a row's parts sit, from the right edge of the panel's content: the reset button, then the
// name column, as wide as the longest name shown (a long name never runs into the button).
struct RowLayout {
  float reset = 0;  // the reset button's width
  float name = 0;   // from the name column's left edge to the content's right edge
};

RowLayout rowLayout(const std::vector<Control>& controls) {
  const ImGuiStyle& style = ImGui::GetStyle();
  float longest = 0;
  for (const Control& c : controls) longest = std::max(longest, ImGui::CalcTextSize(c.spec->name.c_str()).x);
  RowLayout layout;
  layout.reset = ImGui::CalcTextSize("R").x + 2 * style.FramePadding.x;  // a SmallButton's width
  layout.name = layout.reset + style.ItemSpacing.x + longest;
  return layout;
}

// The popup that takes a typed value for `spec` (opened by the row): Enter sets it, as --set
// reads text; a value it does not take goes to the messages.
void typedEntry(PlayerSession& session, UiState& ui, const ParameterSpec& spec) {
  if (!ImGui::BeginPopup("type")) return;
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  ImGui::SetNextItemWidth(160);
  if (ImGui::InputText("##typed", ui.typedValue.data(), ui.typedValue.size(),
                       ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    try {
      session.parameters().set(spec.name, parseParameterText(spec, ui.typedValue.data(), "parameter " + inQuotes(spec.name)));
    } catch (const InputError& e) {
      session.messages().push_back({e.what(), true});
    }
    ImGui::CloseCurrentPopup();
  }
  ImGui::TextDisabled("%s: Enter sets it; accepts %s", spec.name.c_str(), formatParameterRange(spec).c_str());
  ImGui::EndPopup();
}

// One row: the slider (checkbox, or choice) showing the value, and the default too once it has
// moved; the name, in the accent colour when moved; a reset button.
void parameterRow(PlayerSession& session, UiState& ui, const Control& c, const RowLayout& layout) {
  LiveParameters& params = session.parameters();
  const ParameterSpec& spec = *c.spec;
  ImGui::PushID(spec.name.c_str());
  // The slider or choice fills the row up to the name column, a spacing short of it.
  const float valueWidth = ImGui::GetContentRegionAvail().x - layout.name - ImGui::GetStyle().ItemSpacing.x;
  const bool moved = c.value != c.initial;
  bool changed = false;
  double value = c.value;
  if (spec.kind == ParameterKind::kToggle) {
    bool on = c.value != 0;
    changed = ImGui::Checkbox("##on", &on);
    value = on ? 1 : 0;
    if (moved) {
      ImGui::SameLine();
      ImGui::TextDisabled("default %s", formatParameterValue(spec, c.initial).c_str());
    }
  } else if (spec.kind == ParameterKind::kChoice) {
    ImGui::SetNextItemWidth(valueWidth);
    if (ImGui::BeginCombo("##choice", formatParameterValue(spec, c.value).c_str())) {
      for (size_t i = 0; i < spec.choices.size(); ++i) {
        const bool selected = static_cast<size_t>(c.value) == i;
        if (ImGui::Selectable(spec.choices[i].word.c_str(), selected)) {
          value = double(i);
          changed = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", spec.choices[i].meaning.c_str());
      }
      ImGui::EndCombo();
    }
  } else {
    // The slider moves in the control's scale (live_parameters.h) and shows the value itself;
    // double-click or Ctrl+click types any value the parameter takes.
    std::string text = formatParameterValue(spec, c.value);
    if (moved) text += "  (default " + formatParameterValue(spec, c.initial) + ")";
    std::string format;
    for (const char ch : text) format += ch == '%' ? std::string("%%") : std::string(1, ch);
    double s = c.scale.toSlider(c.value);
    ImGui::SetNextItemWidth(valueWidth);
    changed = ImGui::SliderScalar("##value", ImGuiDataType_Double, &s, &c.sliderMin, &c.sliderMax, format.c_str(),
                                  ImGuiSliderFlags_NoInput | ImGuiSliderFlags_NoRoundToFormat);
    if (changed) value = c.scale.fromSlider(s);
    if (ImGui::IsItemHovered() && (ImGui::IsMouseDoubleClicked(0) || (ImGui::GetIO().KeyCtrl && ImGui::IsMouseClicked(0)))) {
      std::snprintf(ui.typedValue.data(), ui.typedValue.size(), "%s", formatParameterValue(spec, c.value).c_str());
      ImGui::OpenPopup("type");
    }
    typedEntry(session, ui, spec);
  }
  if (changed) {
    try {
      params.set(spec.name, value);
    } catch (const InputError& e) {
      session.messages().push_back({e.what(), true});
    }
  }
  ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - layout.name);
  if (moved) ImGui::TextColored(ImVec4(0.96f, 0.70f, 0.35f, 1), "%s", spec.name.c_str());
  else ImGui::TextUnformatted(spec.name.c_str());
  ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - layout.reset);
  if (!moved) ImGui::BeginDisabled();
  if (ImGui::SmallButton("R")) params.reset(spec.name);
  if (!moved) ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Reset to the scene's %s", shown(spec, c.initial).c_str());
  ImGui::PopID();
}

}  // namespace

void parametersPanel(PlayerSession& session, UiState& ui) {
  LiveParameters& params = session.parameters();
  // A copy: a row's change rewrites the list's values while it is walked.
  const std::vector<Control> all = params.all();
  // One name column for every row, folded ones too: it stays put when the fold opens.
  const RowLayout layout = rowLayout(all);
  ImGui::TextDisabled("Solver");
  for (const Control& c : all)
    if (!dynamicsControl(c)) parameterRow(session, ui, c, layout);
  ImGui::Spacing();
  ImGui::TextDisabled("Dynamics");
  // The toggle first, then what shapes the motion; the gusts and the controller's budget folded
  // away until asked for.
  const auto folded = [](const Control& c) {
    return c.spec->name == "gust" || c.spec->name == "gust_frequency" || c.spec->name == "settle" ||
           c.spec->name == "max_deviation";
  };
  for (const Control& c : all)
    if (c.spec->name == "dynamics") parameterRow(session, ui, c, layout);
  for (const Control& c : all)
    if (dynamicsControl(c) && c.spec->name != "dynamics" && !folded(c)) parameterRow(session, ui, c, layout);
  if (ImGui::TreeNode("gusts, settling, deviation budget")) {
    for (const Control& c : all)
      if (folded(c)) parameterRow(session, ui, c, layout);
    ImGui::TreePop();
  }
  ImGui::Spacing();
  ImGui::Separator();
  if (ImGui::Button("Reset all")) params.resetAll();
  ImGui::SameLine();
  if (ImGui::Button("Save parameters")) session.saveParameters();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Write the tuned values into %s (Ctrl+S)", session.scenePath().c_str());
  const SolveWorker::Stats stats = session.worker().stats();
  if (stats.busy) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.96f, 0.70f, 0.30f, 1), "solving...");
  }
}

}  // namespace ib::play
