// The transport bar along the bottom of the window: buttons, loop and ping-pong, speed, the frame
// and time readout, the in / out range, and the scrubber with the timeline's marks at their times.
#include "player/player_ui.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ib::play {

namespace {

constexpr ImU32 kTrack = IM_COL32(38, 40, 46, 255);
constexpr ImU32 kRange = IM_COL32(70, 74, 84, 255);
constexpr ImU32 kCached = IM_COL32(90, 150, 110, 255);
constexpr ImU32 kKeyMark = IM_COL32(235, 200, 70, 255);
constexpr ImU32 kBreakdown = IM_COL32(120, 180, 235, 255);
constexpr ImU32 kPlayhead = IM_COL32(245, 140, 46, 255);
constexpr ImU32 kTicks = IM_COL32(110, 114, 124, 255);
constexpr ImU32 kRelease = IM_COL32(235, 80, 80, 255);  // a cut lets go
constexpr ImU32 kGlue = IM_COL32(80, 200, 235, 255);    // a cut glues

// The scrubber: the whole timeline as a track, the loop range lighter, solved frames as a thin
// green line, a tick every frame (or every 5th / 10th when crowded), the marks as diamonds
// (keys yellow with their names, breakdowns blue), each cut's release (red) and glue (cyan) as a
// line across the track with a triangle pointing down (lets go) or up (glues), its name on
// hover, and the playhead. Click or drag to scrub. In edit mode (`editing` has callbacks) a press on
// a mark or a cut's marker picks it up instead, and it is dropped on the nearest frame.
void scrubber(PlayerSession& session, TimelineEditing& editing) {
  Transport& transport = session.transport();
  const Timeline& timeline = session.scene().scene.timeline;
  const int frames = transport.frameCount();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = 42;
  ImGui::InvisibleButton("scrubber", ImVec2(width, height));
  const bool weights = session.weightsMode();
  const float mouseX = ImGui::GetIO().MousePos.x;
  const auto frameAt = [&](float x) {
    return std::clamp(std::round((x - origin.x - 6) / std::max(1.0f, width - 12) * std::max(1, frames - 1)), 0.0f, float(frames - 1));
  };
  const auto markFrame = [&](const TimelineMark& mark) { return (mark.time - timeline.start()) * timeline.fps(); };
  if (editing.moveMark && ImGui::IsItemClicked() && !weights) {
    // The nearest mark or cut marker within 7 px of the press, if any, is picked up.
    float best = 7;
    for (size_t i = 0; i < timeline.marks().size(); ++i) {
      const float d = std::abs(origin.x + 6 + static_cast<float>(markFrame(timeline.marks()[i]) / std::max(1, frames - 1)) * (width - 12) - mouseX);
      if (d <= best && ImGui::GetIO().MousePos.y < origin.y + 26) best = d, editing.draggedMark = static_cast<int>(i);
    }
    for (const CutEvent& event : session.cutEvents()) {
      const float d = std::abs(origin.x + 6 + static_cast<float>(event.frame) / std::max(1, frames - 1) * (width - 12) - mouseX);
      if (d <= best && ImGui::GetIO().MousePos.y >= origin.y + 26)
        best = d, editing.draggedCut = event.cut, editing.draggedCutFrame = event.frame, editing.draggedMark = -1;
    }
    if (editing.draggedMark >= 0 && editing.selectMark) editing.selectMark(editing.draggedMark);
    editing.pressX = mouseX;
  }
  const bool dragging = editing.draggedMark >= 0 || !editing.draggedCut.empty();
  if (dragging) {
    editing.dragFrame = frameAt(mouseX);
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {  // dropped; a click that did not move only selects
      const bool moved = std::abs(mouseX - editing.pressX) > 3;
      if (moved && editing.draggedMark >= 0) editing.moveMark(editing.draggedMark, timeline.start() + editing.dragFrame / timeline.fps());
      else if (moved && !editing.draggedCut.empty()) editing.moveCut(editing.draggedCut, static_cast<int>(editing.dragFrame));
      editing.draggedMark = -1;
      editing.draggedCut.clear();
    }
  } else if (ImGui::IsItemActive() && !weights) {
    const float u = std::clamp((ImGui::GetIO().MousePos.x - origin.x) / width, 0.0f, 1.0f);
    transport.pause();
    transport.goTo(static_cast<int>(std::lround(u * (frames - 1))));
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float top = origin.y + 14, bottom = origin.y + height - 4;
  editing.x0 = origin.x + 6;
  editing.width = width - 12;
  editing.markY = top + 9;
  editing.cutY = bottom - 6;
  auto xOf = [&](double frame) { return origin.x + 6 + static_cast<float>(frame / std::max(1, frames - 1)) * (width - 12); };
  draw->AddRectFilled(ImVec2(origin.x, top), ImVec2(origin.x + width, bottom), kTrack, 3);
  draw->AddRectFilled(ImVec2(xOf(transport.in()) - 2, top), ImVec2(xOf(transport.out()) + 2, bottom), kRange, 3);
  for (int f = 0; f < frames; ++f)
    if (session.cachedFrame(f))
      draw->AddLine(ImVec2(xOf(std::max(0.0, f - 0.5)), bottom - 2), ImVec2(xOf(std::min(frames - 1.0, f + 0.5)), bottom - 2), kCached, 3);
  const float spacing = (width - 12) / std::max(1, frames - 1);
  const int every = spacing >= 6 ? 1 : spacing >= 1.5f ? 5 : 10;
  for (int f = 0; f < frames; f += every)
    draw->AddLine(ImVec2(xOf(f), bottom - (f % (every * 5) == 0 ? 10 : 5)), ImVec2(xOf(f), bottom), kTicks);
  for (size_t i = 0; i < timeline.marks().size(); ++i) {
    const TimelineMark& mark = timeline.marks()[i];
    const bool dragged = editing.draggedMark == static_cast<int>(i);
    const double frame = dragged ? editing.dragFrame : markFrame(mark);
    if (frame > frames - 1 + 1e-9) continue;  // a looping timeline's end repeats its start
    const float x = xOf(frame), y = top + 9;
    const bool key = mark.label != "breakdown";
    const float r = key ? 6.0f : 4.5f;
    draw->AddQuadFilled(ImVec2(x, y - r), ImVec2(x + r, y), ImVec2(x, y + r), ImVec2(x - r, y), key ? kKeyMark : kBreakdown);
    if (dragged || editing.selectedMark == static_cast<int>(i))
      draw->AddQuad(ImVec2(x, y - r - 2), ImVec2(x + r + 2, y), ImVec2(x, y + r + 2), ImVec2(x - r - 2, y), IM_COL32(255, 255, 255, 255), 2);
    const float textWidth = ImGui::CalcTextSize(mark.label.c_str()).x;  // left of the mark where the track ends
    const float textX = x + r + 2 + textWidth > origin.x + width ? x - r - 2 - textWidth : x + r + 2;
    draw->AddText(ImVec2(textX, origin.y), key ? kKeyMark : kBreakdown, mark.label.c_str());
  }
  for (const CutEvent& event : session.cutEvents()) {
    if (event.frame > frames - 1) continue;
    const bool dragged = event.cut == editing.draggedCut && event.frame == editing.draggedCutFrame;
    const float x = xOf(dragged ? editing.dragFrame : event.frame), y = bottom - 6;
    const ImU32 colour = event.glue ? kGlue : kRelease;
    draw->AddLine(ImVec2(x, top), ImVec2(x, bottom), colour, 2);
    if (event.glue) draw->AddTriangleFilled(ImVec2(x - 5, y + 4), ImVec2(x + 5, y + 4), ImVec2(x, y - 4), colour);
    else draw->AddTriangleFilled(ImVec2(x - 5, y - 4), ImVec2(x + 5, y - 4), ImVec2(x, y + 4), colour);
    if (ImGui::IsMouseHoveringRect(ImVec2(x - 5, top), ImVec2(x + 5, bottom)))
      ImGui::SetTooltip("cut \"%s\" %s at frame %d", event.cut.c_str(), event.glue ? "glues" : "lets go", event.frame);
  }
  if (!weights) {
    const float x = xOf(transport.frame());
    draw->AddLine(ImVec2(x, origin.y + 8), ImVec2(x, bottom + 2), kPlayhead, 2);
    draw->AddTriangleFilled(ImVec2(x - 5, origin.y + 6), ImVec2(x + 5, origin.y + 6), ImVec2(x, origin.y + 13), kPlayhead);
  }
}

}  // namespace

void transportPanel(PlayerSession& session, UiState& ui) {
  Transport& transport = session.transport();
  ImGui::SetNextWindowPos(ImVec2(0, static_cast<float>(ui.height) - kTransportHeight));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(ui.width) - kSidePanelWidth, kTransportHeight));
  ImGui::Begin("Transport", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const bool weights = session.weightsMode();
  if (weights) ImGui::BeginDisabled();
  if (ImGui::Button("|<")) transport.toStart();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("To the in point (Home)");
  ImGui::SameLine();
  if (ImGui::Button("<<")) transport.step(-10);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back ten frames (Down)");
  ImGui::SameLine();
  if (ImGui::Button(" < ")) transport.step(-1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back one frame (Left)");
  ImGui::SameLine();
  ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.55f, 0.34f, 0.14f, 1));
  if (ImGui::Button(transport.playing() ? " Pause " : "  Play  ")) transport.toggle();
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Play / pause (Space)");
  ImGui::SameLine();
  if (ImGui::Button(" > ")) transport.step(1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Forward one frame (Right)");
  ImGui::SameLine();
  if (ImGui::Button(">>")) transport.step(10);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Forward ten frames (Up)");
  ImGui::SameLine();
  if (ImGui::Button(">|")) transport.toEnd();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("To the out point (End)");
  ImGui::SameLine(0, 18);
  bool loop = transport.loop(), pingPong = transport.pingPong();
  if (ImGui::Checkbox("Loop", &loop)) transport.setLoop(loop);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Loop the in..out range (L)");
  ImGui::SameLine();
  if (ImGui::Checkbox("Ping-pong", &pingPong)) transport.setPingPong(pingPong);
  ImGui::SameLine(0, 18);
  ImGui::SetNextItemWidth(120);
  float speed = static_cast<float>(transport.speed());
  if (ImGui::SliderFloat("##speed", &speed, 0.1f, 4.0f, "speed %.2fx", ImGuiSliderFlags_Logarithmic)) transport.setSpeed(speed);
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) transport.setSpeed(1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Playback speed, 0.1x to 4x (right-click: 1x)");
  scrubber(session, ui.timelineEditing);
  ImGui::SetNextItemWidth(70);
  int in = transport.in(), out = transport.out();
  if (ImGui::DragInt("##in", &in, 0.2f, 0, transport.frameCount() - 1, "in %d")) transport.setRange(in, out);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("In point (I: set to the current frame)");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  if (ImGui::DragInt("##out", &out, 0.2f, 0, transport.frameCount() - 1, "out %d")) transport.setRange(in, out);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Out point (O: set to the current frame)");
  ImGui::SameLine();
  if (ImGui::SmallButton("all")) transport.setRange(0, transport.frameCount() - 1);
  if (weights) ImGui::EndDisabled();
  ImGui::SameLine(0, 18);
  ImGui::TextDisabled("%d frames, %g fps", transport.frameCount(), transport.fps());
  char readout[64];
  if (weights) std::snprintf(readout, sizeof readout, "weights mode");
  else std::snprintf(readout, sizeof readout, "frame %d / %d   %.3f s", transport.frame(), transport.frameCount() - 1, transport.time());
  const float afterLast = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x + 18;
  ImGui::SameLine(std::max(afterLast, ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize(readout).x));
  ImGui::TextUnformatted(readout);
  ImGui::End();
}

}  // namespace ib::play
