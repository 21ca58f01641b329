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

void parameterRow(PlayerSession& session, const Parameter& p) {
  LiveParameters& params = session.parameters();
  ImGui::PushID(p.name.c_str());
  const float resetWidth = 22;
  bool changed = false;
  double value = p.value;
  if (p.toggle) {
    bool on = p.value != 0;
    changed = ImGui::Checkbox(p.name.c_str(), &on);
    value = on ? 1 : 0;
  } else {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 110 - resetWidth);
    const ImGuiSliderFlags flags = p.logScale ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
    changed = ImGui::SliderScalar(p.name.c_str(), ImGuiDataType_Double, &value, &p.min, &p.max, "%.4g", flags);
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\ndefault %g, range %g..%g%s\nCtrl+click to type a value",
                      p.help.c_str(), p.initial, p.min, p.max, p.logScale ? " (log scale)" : "");
  if (changed) {
    try {
      params.set(p.name, value);
    } catch (const InputError& e) {
      session.messages().push_back({e.what(), true});
    }
  }
  ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - resetWidth);
  const bool moved = p.value != p.initial;
  if (!moved) ImGui::BeginDisabled();
  if (ImGui::SmallButton("R")) params.reset(p.name);
  if (!moved) ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Reset to the scene's %g", p.initial);
  if (moved) {
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - resetWidth - 78);
    ImGui::TextDisabled("(was %.3g)", p.initial);
  }
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
