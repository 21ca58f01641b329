// Files: the scene being played and how to open another (drop its scene.json onto the window), a
// reload's progress, reload and save, the screenshot key, and the messages; the latest error as a
// banner over the picture; and the help panel listing every shortcut.
#include "player/player_ui.h"
#include "player/shortcuts.h"

#include <imgui.h>

#include <algorithm>

namespace ib::play {

namespace {

const ImVec4 kError(0.95f, 0.42f, 0.36f, 1);
const ImVec4 kNotice(0.60f, 0.80f, 0.62f, 1);

}  // namespace

void filesPanel(PlayerSession& session, UiState& ui) {
  ImGui::TextDisabled("Scene");
  ImGui::TextWrapped("%s", session.scenePath().c_str());
  ImGui::TextDisabled("Drop a scene.json onto the window to open it. Edits to the scene or its drawings are picked up.");
  SceneReloader& reloader = session.reloader();
  if (reloader.busy()) {
    ImGui::ProgressBar(static_cast<float>(reloader.progress()), ImVec2(-1, 0), reloader.stage().c_str());
    ImGui::TextDisabled("the last good scene plays meanwhile");
  }
  if (ImGui::Button("Reload now")) reloader.reloadNow();
  ImGui::SameLine();
  if (ImGui::Button("Save parameters")) session.saveParameters();
  ImGui::SameLine();
  if (ImGui::Button("Screenshot")) ui.screenshotRequested = true;
  ImGui::Spacing();
  ImGui::TextDisabled("Messages");
  ImGui::BeginChild("messages", ImVec2(0, 180), true);
  for (const PlayerSession::Message& m : session.messages()) {
    ImGui::PushStyleColor(ImGuiCol_Text, m.error ? kError : kNotice);
    ImGui::TextWrapped("%s", m.text.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::EndChild();
  if (!session.messages().empty() && ImGui::SmallButton("Clear")) session.messages().clear();
}

void messageBanner(PlayerSession& session, const UiState& ui) {
  std::vector<PlayerSession::Message>& messages = session.messages();
  if (messages.empty() || !messages.back().error) return;
  const float width = std::min(560.0f, static_cast<float>(ui.canvas.x1 - ui.canvas.x0) - 300);
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(ui.canvas.x1) - width - 10, static_cast<float>(ui.canvas.y0) + 10));
  ImGui::SetNextWindowSize(ImVec2(width, 0));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.32f, 0.10f, 0.10f, 1.00f));
  ImGui::Begin("Error", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.85f, 0.82f, 1));
  ImGui::TextWrapped("%s", messages.back().text.c_str());
  ImGui::PopStyleColor();
  if (ImGui::SmallButton("Dismiss")) messages.back().error = false;
  ImGui::End();
  ImGui::PopStyleColor();
}

void helpPanel() {
  if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed, 110);
    ImGui::TableSetupColumn("does");
    for (const ShortcutHelp& row : shortcutHelp()) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextColored(ImVec4(0.96f, 0.70f, 0.35f, 1), "%s", row.keys);
      ImGui::TableSetColumnIndex(1);
      ImGui::TextUnformatted(row.does);
    }
    ImGui::EndTable();
  }
  ImGui::Spacing();
  ImGui::TextWrapped("Marks on the scrubber: keys (yellow) and breakdowns (blue) at their times; solved frames are "
                     "underlined green. A parameter change re-solves from the shown frame; the UI never waits for it.");
}

}  // namespace ib::play
