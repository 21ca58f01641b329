// The view: overlays (wireframe, cohesive edges with the held pairs marked, features), onion
// skins, the backdrop, zoom and fit, the artwork's sampling and which multimesh plays; plus the
// side panel's tabs that hold every panel, and the held-pair marks drawn over the picture.
#include "player/player_ui.h"

#include <imgui.h>

#include <algorithm>

namespace ib::play {

PixelRect canvasRect(int width, int height) {
  return {0, 0, std::max(1.0, width - double(kSidePanelWidth)), std::max(1.0, height - double(kTransportHeight))};
}

void viewPanel(PlayerSession& session, UiState& ui) {
  ViewSettings& view = ui.view;
  ImGui::TextDisabled("Overlays");
  ImGui::Checkbox("Wireframe", &view.overlays.wireframe);
  ImGui::SameLine(170);
  ImGui::Checkbox("Features", &view.overlays.features);
  ImGui::Checkbox("Cohesive edges", &view.overlays.cohesive);
  ImGui::SameLine(170);
  if (!view.overlays.cohesive) ImGui::BeginDisabled();
  ImGui::Checkbox("Held pairs", &view.heldPairs);
  if (!view.overlays.cohesive) ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Mark the cohesive pairs that hold in the shown frame (green)");

  ImGui::Spacing();
  ImGui::TextDisabled("Onion skin");
  ImGui::SetNextItemWidth(120);
  ImGui::SliderInt("frames each side", &view.onion.neighbours, 0, render::kMaxOnionSkins / 2);
  ImGui::SetNextItemWidth(120);
  ImGui::SliderFloat("opacity", &view.onion.opacity, 0.05f, 1.0f, "%.2f");
  if (session.weightsMode()) ImGui::TextDisabled("(the timeline's neighbours; none in weights mode)");

  ImGui::Spacing();
  ImGui::TextDisabled("Background");
  ImGui::ColorEdit3("colour", view.backdrop.colour.data(), ImGuiColorEditFlags_NoInputs);
  ImGui::SameLine(170);
  ImGui::Checkbox("Checkerboard", &view.backdrop.checkerboard);
  if (view.backdrop.checkerboard) {
    ImGui::ColorEdit3("second colour", view.backdrop.second.data(), ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine(170);
    ImGui::SetNextItemWidth(90);
    ImGui::SliderInt("square", &view.backdrop.square, 4, 64, "%d px");
  }

  ImGui::Spacing();
  ImGui::TextDisabled("Zoom");
  ImGui::Text("%.0f%% of the fitted size", 100 * ui.navigation.zoom());
  ImGui::SameLine();
  if (ImGui::SmallButton("Fit (F)")) ui.navigation.fit();
  ImGui::TextDisabled("wheel: zoom at the pointer; drag: pan");
  bool nearest = view.sampling == render::Sampling::kNearest;
  if (ImGui::Checkbox("Nearest-neighbour sampling (pixel art)", &nearest))
    view.sampling = nearest ? render::Sampling::kNearest : render::Sampling::kLinear;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Each pixel shows the drawing's nearest texel, so magnified pixel art keeps hard edges;\n"
                      "off: trilinear filtering, smooth line art at any zoom");

  ImGui::Spacing();
  ImGui::TextDisabled("Multimesh");
  bool initial = session.initialMap();
  if (!session.hasInitialMap()) ImGui::BeginDisabled();
  if (ImGui::RadioButton("Comesh-optimized", !initial)) session.setInitialMap(false);
  ImGui::SameLine();
  if (ImGui::RadioButton("initial map", initial)) session.setInitialMap(true);
  if (!session.hasInitialMap()) ImGui::EndDisabled();
  if (!session.hasInitialMap() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Only one multimesh is known: build it with `inbetween mesh` to keep both");
  const render::RenderMesh& mesh = session.renderMesh();
  ImGui::TextDisabled("%d vertices, %zu triangles, %d keys", mesh.vertexCount, mesh.triangles.size(), session.keyCount());
}

void sidePanel(PlayerSession& session, UiState& ui) {
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(ui.width) - kSidePanelWidth, 0));
  ImGui::SetNextWindowSize(ImVec2(kSidePanelWidth, static_cast<float>(ui.height)));
  ImGui::Begin("inbetween", nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse);
  // Weights mode switched on (a key, the command's --weights): its tab comes to the front.
  const bool showWeights = session.weightsMode() && !ui.weightsModeShown;
  ui.weightsModeShown = session.weightsMode();
  if (ImGui::BeginTabBar("tabs")) {
    if (ui.editPanel && ImGui::BeginTabItem("Edit")) {
      ui.editPanel();
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Parameters")) {
      parametersPanel(session, ui);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Weights", nullptr, showWeights ? ImGuiTabItemFlags_SetSelected : 0)) {
      weightsPanel(session);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("View")) {
      viewPanel(session, ui);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Files")) {
      filesPanel(session, ui);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Help")) {
      helpPanel();
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
}

void heldPairMarks(const PlayerSession& session, const AnimationFrame& frame, const render::ViewBox& view, const UiState& ui) {
  if (!ui.view.overlays.cohesive || !ui.view.heldPairs) return;
  const render::CutSides& cuts = session.renderMesh().cutSides;
  if (frame.heldPairs.size() != cuts.pairOfTerm.size() || frame.x.rows() != session.renderMesh().vertexCount) return;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  auto at = [&](int v) {
    const Eigen::Vector2d p = toWindow(view, ui.width, ui.height, frame.x.row(v).transpose());
    return ImVec2(static_cast<float>(p.x()), static_cast<float>(p.y()));
  };
  for (size_t term = 0; term < frame.heldPairs.size(); ++term) {
    if (!frame.heldPairs[term]) continue;
    const CohesivePair& pair = cuts.pairs[cuts.pairOfTerm[term]];
    draw->AddLine(at(pair.a), at(pair.b), IM_COL32(60, 220, 110, 255), 3);
    draw->AddCircleFilled(at(pair.a), 2.5f, IM_COL32(60, 220, 110, 255));
    draw->AddCircleFilled(at(pair.b), 2.5f, IM_COL32(60, 220, 110, 255));
  }
}

}  // namespace ib::play
