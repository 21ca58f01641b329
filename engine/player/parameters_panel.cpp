// The parameters: a slider (log-scaled where the parameter asks) or a toggle per live parameter,
// each with its default and a reset; the solver's and the dynamics' in two groups. A change goes
// to the solve worker in the session's next update.
#include "player/player_ui.h"

#include "core/error.h"

#include <imgui.h>

#include <cstdio>

namespace ib::play {

namespace {

bool dynamicsParameter(const std::string& name) {
  return name == "dynamics" || name == "epsilon" || name == "mu" || name == "gravity_x" || name == "gravity_y" ||
         name == "wind_x" || name == "wind_y" || name == "anchor";
}

// One row: the slider (or checkbox) showing the value, and the default too once it has moved;
// the name, in the accent colour when moved; a reset button.
void parameterRow(PlayerSession& session, const Parameter& p) {
  LiveParameters& params = session.parameters();
  ImGui::PushID(p.name.c_str());
  const float resetWidth = 22;
  const bool moved = p.value != p.initial;
  char format[64];
  std::snprintf(format, sizeof format, moved ? "%%.4g  (default %.4g)" : "%%.4g", p.initial);
  bool changed = false;
  double value = p.value;
  if (p.toggle) {
    bool on = p.value != 0;
    changed = ImGui::Checkbox("##on", &on);
    value = on ? 1 : 0;
    if (moved) {
      ImGui::SameLine();
      ImGui::TextDisabled("default %s", p.initial != 0 ? "on" : "off");
    }
  } else {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 100 - resetWidth);
    const ImGuiSliderFlags flags = p.logScale ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
    changed = ImGui::SliderScalar("##value", ImGuiDataType_Double, &value, &p.min, &p.max, format, flags);
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\ndefault (the scene's) %g, range %g..%g%s\nCtrl+click to type a value", p.help.c_str(), p.initial,
                      p.min, p.max, p.logScale ? ", log scale" : "");
  if (changed) {
    try {
      params.set(p.name, value);
    } catch (const InputError& e) {
      session.messages().push_back({e.what(), true});
    }
  }
  ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 94 - resetWidth);
  if (moved) ImGui::TextColored(ImVec4(0.96f, 0.70f, 0.35f, 1), "%s", p.name.c_str());
  else ImGui::TextUnformatted(p.name.c_str());
  ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - resetWidth);
  if (!moved) ImGui::BeginDisabled();
  if (ImGui::SmallButton("R")) params.reset(p.name);
  if (!moved) ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Reset to the scene's %g", p.initial);
  ImGui::PopID();
}

}  // namespace

void parametersPanel(PlayerSession& session) {
  LiveParameters& params = session.parameters();
  // A copy: a row's change rewrites the list's values while it is walked.
  const std::vector<Parameter> all = params.all();
  ImGui::TextDisabled("Solver");
  for (const Parameter& p : all)
    if (!dynamicsParameter(p.name)) parameterRow(session, p);
  ImGui::Spacing();
  ImGui::TextDisabled("Dynamics");
  for (const Parameter& p : all)
    if (dynamicsParameter(p.name)) parameterRow(session, p);
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
