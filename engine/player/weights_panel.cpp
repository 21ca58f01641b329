// Weights mode: a slider per key, kept convex as one moves (the others share the rest in their
// proportions), and with three keys a triangle pad whose corners are the keys: the dot's
// barycentric coordinates are the weights.
#include "player/player_ui.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace ib::play {

namespace {

// Key `key` set to `value` in [0, 1]; the others scaled to share 1 - value as they did, or
// evenly when they were all 0.
Eigen::VectorXd moved(const Eigen::VectorXd& w, int key, double value) {
  Eigen::VectorXd out = w;
  const double others = w.sum() - w[key];
  for (int k = 0; k < w.size(); ++k)
    if (k != key) out[k] = others > 1e-12 ? w[k] * (1 - value) / others : (1 - value) / std::max<Eigen::Index>(1, w.size() - 1);
  out[key] = value;
  return out;
}

// The three keys' triangle pad, `side` pixels wide.
void trianglePad(PlayerSession& session, const std::vector<std::string>& names) {
  const float side = std::min(ImGui::GetContentRegionAvail().x - 20, 240.0f), h = side * 0.866f;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 corners[3] = {ImVec2(origin.x + 10 + side / 2, origin.y + 16), ImVec2(origin.x + 10, origin.y + 16 + h),
                             ImVec2(origin.x + 10 + side, origin.y + 16 + h)};
  ImGui::InvisibleButton("pad", ImVec2(side + 20, h + 34));
  if (ImGui::IsItemActive()) {  // barycentric coordinates of the mouse, clamped into the triangle
    const ImVec2 m = ImGui::GetIO().MousePos;
    const double det = (corners[1].y - corners[2].y) * (corners[0].x - corners[2].x) +
                       (corners[2].x - corners[1].x) * (corners[0].y - corners[2].y);
    double l0 = ((corners[1].y - corners[2].y) * (m.x - corners[2].x) + (corners[2].x - corners[1].x) * (m.y - corners[2].y)) / det;
    double l1 = ((corners[2].y - corners[0].y) * (m.x - corners[2].x) + (corners[0].x - corners[2].x) * (m.y - corners[2].y)) / det;
    l0 = std::max(0.0, l0);
    l1 = std::max(0.0, l1);
    double l2 = std::max(0.0, 1 - l0 - l1);
    const double sum = l0 + l1 + l2;
    session.setWeights(Eigen::Vector3d(l0 / sum, l1 / sum, l2 / sum));
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddTriangleFilled(corners[0], corners[1], corners[2], IM_COL32(48, 51, 58, 255));
  draw->AddTriangle(corners[0], corners[1], corners[2], IM_COL32(140, 144, 154, 255), 1.5f);
  const Eigen::VectorXd& w = session.weights();
  const ImVec2 dot(static_cast<float>(w[0] * corners[0].x + w[1] * corners[1].x + w[2] * corners[2].x),
                   static_cast<float>(w[0] * corners[0].y + w[1] * corners[1].y + w[2] * corners[2].y));
  draw->AddCircleFilled(dot, 6, IM_COL32(245, 140, 46, 255));
  draw->AddCircle(dot, 6, IM_COL32(20, 20, 20, 255), 0, 1.5f);
  const ImVec2 labels[3] = {ImVec2(corners[0].x + 8, corners[0].y - 14), ImVec2(corners[1].x, corners[1].y + 3),
                            ImVec2(corners[2].x - ImGui::CalcTextSize(names[2].c_str()).x, corners[2].y + 3)};
  for (int k = 0; k < 3; ++k) draw->AddText(labels[k], IM_COL32(235, 200, 70, 255), names[k].c_str());
}

}  // namespace

void weightsPanel(PlayerSession& session) {
  bool on = session.weightsMode();
  if (ImGui::Checkbox("Weights mode", &on)) session.setWeightsMode(on);
  ImGui::SameLine();
  ImGui::TextDisabled("(W)");
  ImGui::TextWrapped("Any inbetween of the keys: the weights below instead of the timeline. Off resumes the timeline.");
  ImGui::Separator();
  const std::vector<std::string> names = session.keyNames();
  const Eigen::VectorXd& w = session.weights();
  if (!on) ImGui::BeginDisabled();
  for (int k = 0; k < static_cast<int>(names.size()); ++k) {
    float value = static_cast<float>(w[k]);
    ImGui::PushID(k);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 90);
    if (ImGui::SliderFloat(names[k].c_str(), &value, 0, 1, "%.3f")) session.setWeights(moved(w, k, std::clamp(value, 0.0f, 1.0f)));
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 28);
    if (ImGui::SmallButton("e")) session.setWeights(Eigen::VectorXd::Unit(w.size(), k));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Key %s alone", names[k].c_str());
    ImGui::PopID();
  }
  if (ImGui::Button("Even blend")) session.setWeights(Eigen::VectorXd::Constant(w.size(), 1.0 / w.size()));
  if (names.size() == 3) {
    ImGui::Spacing();
    ImGui::TextDisabled("Drag the dot through the three keys' blends:");
    trianglePad(session, names);
  }
  if (!on) ImGui::EndDisabled();
}

}  // namespace ib::play
