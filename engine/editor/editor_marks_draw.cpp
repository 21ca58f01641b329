// EditorView::marks: what is drawn over each key's drawing, on ImGui's background draw list
// (after the drawing sheet, before the panels), clipped to the key's view.
#include "editor/editor_view.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace ib::editor {

namespace {

// Arc colours: distinct hues, readable on light and dark drawings (with a dark under-stroke).
constexpr ImU32 kPalette[] = {IM_COL32(230, 25, 75, 255),  IM_COL32(60, 180, 75, 255),  IM_COL32(0, 130, 200, 255),
                              IM_COL32(245, 130, 48, 255), IM_COL32(145, 30, 180, 255), IM_COL32(70, 200, 200, 255),
                              IM_COL32(240, 50, 230, 255), IM_COL32(170, 110, 40, 255), IM_COL32(128, 128, 0, 255),
                              IM_COL32(0, 0, 128, 255)};
constexpr ImU32 kPlainOutline = IM_COL32(90, 90, 100, 255);
constexpr ImU32 kWrongOrder = IM_COL32(255, 0, 0, 255);
constexpr ImU32 kFeature = IM_COL32(255, 255, 255, 255);
constexpr ImU32 kSelected = IM_COL32(255, 210, 0, 255);
constexpr ImU32 kCut = IM_COL32(255, 120, 0, 255);
constexpr ImU32 kInterior = IM_COL32(0, 200, 255, 255);
constexpr ImU32 kShadow = IM_COL32(0, 0, 0, 160);
constexpr float kMinSegment = 1.0f;  // window px: shorter segments of a mark's polyline are merged

ImVec2 im(const Eigen::Vector2d& p) { return ImVec2(static_cast<float>(p.x()), static_cast<float>(p.y())); }

// A name on a dark plate; priority 0 (a view's title, the cursor's position) is always drawn, then
// 1 (the selection, a name the build's error gives), 2 (features, suggestions), 3 (cuts, interior).
struct Label {
  ImVec2 at;
  std::string text;
  ImU32 colour;
  int priority;
};

void drawLabels(ImDrawList* draw, std::vector<Label>& labels) {
  std::stable_sort(labels.begin(), labels.end(), [](const Label& a, const Label& b) { return a.priority < b.priority; });
  std::vector<std::array<float, 4>> placed;  // x0, y0, x1, y1 of the plates drawn
  for (const Label& l : labels) {
    const ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
    const std::array<float, 4> plate{l.at.x - 2, l.at.y - 1, l.at.x + size.x + 2, l.at.y + size.y + 1};
    const auto overlaps = [&](const std::array<float, 4>& o) { return plate[0] < o[2] && o[0] < plate[2] && plate[1] < o[3] && o[1] < plate[3]; };
    if (l.priority > 0 && std::any_of(placed.begin(), placed.end(), overlaps)) continue;
    placed.push_back(plate);
    draw->AddRectFilled(ImVec2(plate[0], plate[1]), ImVec2(plate[2], plate[3]), IM_COL32(0, 0, 0, 170), 3);
    draw->AddText(l.at, l.colour, l.text.c_str());
  }
}

// A stiffness stroke's colour: blue where it softens (kappa < 1), red where it stiffens.
ImU32 kappaColour(double kappa, int alpha) {
  const double t = std::clamp(0.5 + 0.5 * std::log10(kappa) / std::log10(10.0), 0.0, 1.0);
  return IM_COL32(static_cast<int>(255 * t), 60, static_cast<int>(255 * (1 - t)), alpha);
}

}  // namespace

void EditorView::marks() {
  loadDrawings();  // an edit since update() (undo, a dropped key) may have changed the keys
  for (int k = 0; k < static_cast<int>(views_.size()); ++k) keyMarks(k);
}

namespace {

// Whether the last failed build's message names `what` in this key ("key "arch": feature "top" ...").
bool named(const std::string& error, const std::string& key, const std::string& what) {
  return !error.empty() && error.find("\"" + key + "\"") != std::string::npos && error.find("\"" + what + "\"") != std::string::npos;
}

}  // namespace

void EditorView::keyMarks(int key) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const play::PixelRect& r = views_[static_cast<size_t>(key)].rect;
  draw->PushClipRect(ImVec2(static_cast<float>(r.x0), static_cast<float>(r.y0)), ImVec2(static_cast<float>(r.x1), static_cast<float>(r.y1)), true);
  const KeyMarks& marks = session_.marks().keys[static_cast<size_t>(key)];
  // A thumbnail's marks are lighter: thinner, without the dark under-strokes, with fewer points.
  const bool thumbnail = views_[static_cast<size_t>(key)].thumbnail;
  const render::ViewBox view = windowViewOf(key);  // once per key: every mark is mapped through it
  const double scale = width_ / (view.x1 - view.x0);
  const auto at = [&](const Eigen::Vector2d& p) { return im(play::toWindow(view, width_, height_, p)); };
  // Polylines in window pixels, without the points closer than a pixel to the last one kept: a
  // traced outline has a point every drawing pixel or so, thousands in a small view, and each
  // becomes triangles that ImGui builds and lavapipe sets up every frame.
  const auto polyline = [&](const Polyline& points, ImU32 colour, float thickness, bool closed = false) {
    std::vector<ImVec2> screen;
    for (size_t i = 0; i < points.size(); ++i) {
      const ImVec2 q = at(points[i]);
      const bool last = i + 1 == points.size();
      if (!screen.empty() && !last && std::hypot(q.x - screen.back().x, q.y - screen.back().y) < (thumbnail ? 2 : 1) * kMinSegment)
        continue;
      screen.push_back(q);
    }
    if (screen.size() >= 2) draw->AddPolyline(screen.data(), static_cast<int>(screen.size()), colour, closed ? ImDrawFlags_Closed : 0, thickness);
  };
  // Names are drawn last, over every mark, most important first; one that would cover a name
  // already drawn is left out (a small view of a key with many features), and a thumbnail shows
  // only its title.
  std::vector<Label> labels;
  const auto label = [&](const ImVec2& p, const std::string& text, ImU32 colour, int priority) {
    if (!thumbnail || priority == 0) labels.push_back({p, text, colour, priority});
  };

  // Painted stiffness, under everything else (the reference key's strokes).
  for (const StrokeMark& s : session_.marks().strokes) {
    if (s.key != marks.name) continue;
    const float width = static_cast<float>(2 * s.radius * scale);
    if (s.points.size() == 1) draw->AddCircleFilled(at(s.points[0]), width / 2, kappaColour(s.kappa, 90));
    polyline(s.points, kappaColour(s.kappa, 90), width);
  }
  if (paintKey_ == key) polyline(paintPoints_, kappaColour(tools_.brushKappa, 90), static_cast<float>(2 * tools_.brushRadius * scale));

  // The outline, arc by arc.
  for (const OutlineArc& arc : session_.arcs(key)) {
    if (!thumbnail) polyline(arc.points, kShadow, 5);
    const ImU32 colour = arc.unmatched ? kWrongOrder : arc.colour < 0 ? kPlainOutline : kPalette[arc.colour % std::size(kPalette)];
    polyline(arc.points, colour, arc.unmatched ? 4.0f : thumbnail ? 2.0f : 3.0f);
  }

  // Cuts, with their kind and name at the first point.
  for (const CutMark& c : marks.cuts) {
    polyline(c.points, kShadow, 5);
    polyline(c.points, kCut, 3);
    for (const Eigen::Vector2d& p : c.points) draw->AddCircleFilled(at(p), 3, kCut);
    if (!c.points.empty())
      label(ImVec2(at(c.points.front()).x + 6, at(c.points.front()).y + 4), c.name + " (" + c.kind + ")",
            named(buildError_, marks.name, c.name) ? kWrongOrder : kCut, named(buildError_, marks.name, c.name) ? 1 : 3);
  }
  if (cutKey_ == key && !cutPoints_.empty()) {
    Polyline preview = cutPoints_;
    if (hoverKey_ == key) preview.push_back(hover_);
    polyline(preview, kCut, 2);
    for (const Eigen::Vector2d& p : cutPoints_) draw->AddCircleFilled(at(p), 3, kCut);
  }

  // Interior features: a cross, and the disc that moves with the point.
  for (const auto& [name, p] : marks.interior) {
    const ImVec2 c = at(p);
    const bool chosen = key == selectedKey_ && selectedInterior_ && name == selected_;
    const ImU32 colour = chosen ? kSelected : kInterior;
    if (marks.radii.count(name)) draw->AddCircle(c, static_cast<float>(marks.radii.at(name) * scale), colour, 0, 2);
    draw->AddLine(ImVec2(c.x - 6, c.y), ImVec2(c.x + 6, c.y), colour, 2);
    draw->AddLine(ImVec2(c.x, c.y - 6), ImVec2(c.x, c.y + 6), colour, 2);
    label(ImVec2(c.x + 7, c.y + 3), name, named(buildError_, marks.name, name) ? kWrongOrder : colour,
          chosen || named(buildError_, marks.name, name) ? 1 : 3);
  }
  if (dragging_ && selectedInterior_ && selectedKey_ == key && (draggingRadius_ || !marks.interior.count(selected_))) {
    draw->AddCircle(at(dragAt_), static_cast<float>((hover_ - dragAt_).norm() * scale), kSelected, 0, 2);
    draw->AddCircleFilled(at(dragAt_), 3, kSelected);
  }

  // Features with their names; the one being dragged where it goes.
  for (const auto& [name, p0] : marks.features) {
    const bool chosen = key == selectedKey_ && !selectedInterior_ && name == selected_;
    const Eigen::Vector2d p = chosen && dragging_ ? dragAt_ : p0;
    const ImVec2 c = at(p);
    if (!thumbnail) draw->AddCircleFilled(c, 6, kShadow);
    draw->AddCircleFilled(c, thumbnail ? 3.0f : 4.5f, chosen ? kSelected : kFeature);
    label(ImVec2(c.x + 7, c.y - 16), name, named(buildError_, marks.name, name) ? kWrongOrder : chosen ? kSelected : kFeature,
          chosen || named(buildError_, marks.name, name) ? 1 : 2);
  }

  // Suggested features: hollow, numbered, until accepted or dropped.
  for (size_t i = 0; i < suggestions_.size(); ++i) {
    if (static_cast<size_t>(key) >= suggestions_[i].at.size()) continue;
    const ImVec2 c = at(suggestions_[i].at[static_cast<size_t>(key)]);
    draw->AddCircle(c, 7, kShadow, 0, 4);
    draw->AddCircle(c, 7, kSelected, 0, 2);
    label(ImVec2(c.x + 9, c.y + 2), "?" + std::to_string(i + 1), kSelected, 2);
  }

  // The view's title: the key, its part, what to do here (a thumbnail: the key, in the colour).
  const bool reference = marks.name == session_.marks().reference;
  std::string title = marks.name + (reference ? (thumbnail ? " (ref)" : "  (reference)") : "");
  const std::optional<MissingFeature> next = session_.nextMissing(lastEditedKey_);
  ImU32 titleColour = IM_COL32(255, 255, 255, 255);
  const bool asked = next && next->key == marks.name;
  if (asked) {
    if (!thumbnail) title += "  - place `" + next->feature + "` here";
    titleColour = kSelected;
  }
  const std::string error = session_.outlineError(key);
  if (!error.empty() || (!buildError_.empty() && buildError_.find("`" + marks.name + "`") != std::string::npos) ||
      (!buildError_.empty() && buildError_.find("\"" + marks.name + "\"") != std::string::npos)) {
    if (!thumbnail) title += "  - does not build";
    titleColour = kWrongOrder;
  }
  label(ImVec2(static_cast<float>(r.x0) + 6, static_cast<float>(r.y0) + 5), title, titleColour, 0);
  if (hoverKey_ == key && !thumbnail) {
    char where[64];
    std::snprintf(where, sizeof where, "x %.1f  y %.1f px", hover_.x(), hover_.y());
    label(ImVec2(static_cast<float>(r.x0) + 6, static_cast<float>(r.y1) - 22), where, IM_COL32(255, 255, 255, 255), 0);
  }
  drawLabels(draw, labels);
  const ImU32 border = key == hoverKey_ || asked ? kSelected : key == focusKey_ && thumbnailLayout() ? IM_COL32(255, 255, 255, 255)
                                                                                                 : IM_COL32(60, 60, 66, 255);
  draw->AddRect(ImVec2(static_cast<float>(r.x0), static_cast<float>(r.y0)), ImVec2(static_cast<float>(r.x1), static_cast<float>(r.y1)), border, 0,
                0, 2);
  draw->PopClipRect();
}

}  // namespace ib::editor
