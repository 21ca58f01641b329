// The readouts over the picture's top-left corner: presented frames per second, the shown
// frame's solve (milliseconds, iterations, converged), the dynamics' deviation, the worker's state
// and a graph of recent frame and solve times.
#include "player/player_ui.h"

#include <imgui.h>

#include <algorithm>
#include <vector>

namespace ib::play {

void Timings::add(double frameSeconds, double solveMilliseconds) {
  frameMs.push_back(static_cast<float>(1000 * frameSeconds));
  solveMs.push_back(static_cast<float>(solveMilliseconds));
  while (frameMs.size() > kHistory) frameMs.pop_front();
  while (solveMs.size() > kHistory) solveMs.pop_front();
  if (frameSeconds > 0) fps = fps == 0 ? 1 / frameSeconds : 0.9 * fps + 0.1 / frameSeconds;
}

namespace {

void graph(const char* label, const std::deque<float>& values, ImVec4 colour) {
  const std::vector<float> v(values.begin(), values.end());
  const float top = v.empty() ? 1 : std::max(16.7f, *std::max_element(v.begin(), v.end()));
  ImGui::PushStyleColor(ImGuiCol_PlotLines, colour);
  ImGui::PlotLines("##graph", v.data(), static_cast<int>(v.size()), 0, label, 0, top * 1.1f, ImVec2(ImGui::GetContentRegionAvail().x, 38));
  ImGui::PopStyleColor();
}

}  // namespace

void readoutsPanel(PlayerSession& session, const UiState& ui) {
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(ui.canvas.x0) + 10, static_cast<float>(ui.canvas.y0) + 10));
  ImGui::SetNextWindowSize(ImVec2(300, 0));
  ImGui::SetNextWindowBgAlpha(0.78f);
  ImGui::Begin("Readouts", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoSavedSettings);
  const std::shared_ptr<const AnimationFrame> frame = session.shown();
  const SolveWorker::Stats stats = session.worker().stats();
  ImGui::Text("%5.1f fps presented", ui.timings.fps);
  if (frame) {
    ImGui::Text("solve %.1f ms, %d iterations,", frame->milliseconds, frame->iterations);
    ImGui::SameLine();
    if (frame->converged) ImGui::TextColored(ImVec4(0.45f, 0.85f, 0.50f, 1), "converged");
    else ImGui::TextColored(ImVec4(0.95f, 0.40f, 0.35f, 1), "not converged");
    ImGui::Text("deviation %.4f shape sizes", frame->deviation);
  } else {
    ImGui::TextDisabled("solving the first frame...");
  }
  ImGui::Text("%s, %d frames cached", stats.busy ? "worker busy" : "worker idle", stats.cachedFrames);
  if (!stats.error.empty()) ImGui::TextColored(ImVec4(0.95f, 0.40f, 0.35f, 1), "solver: %s", stats.error.c_str());
  graph("frame ms", ui.timings.frameMs, ImVec4(0.55f, 0.75f, 0.95f, 1));
  graph("solve ms", ui.timings.solveMs, ImVec4(0.96f, 0.55f, 0.18f, 1));
  ImGui::End();
}

}  // namespace ib::play
