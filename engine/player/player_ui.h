// What the player's panels share: the view settings, the canvas navigation, recent timings and
// the layout, and the panels themselves (one file each), drawn with Dear ImGui once per frame.
#pragma once

#include "output/onion_window.h"
#include "player/player_session.h"
#include "player/view_navigation.h"
#include "renderers/window_presenter.h"

#include <array>
#include <deque>
#include <functional>
#include <string>

namespace ib::play {

struct ViewSettings {
  render::Overlays overlays;
  bool heldPairs = true;  // with the cohesive edges: the pairs that hold marked (green)
  render::OnionStyle onion;
  render::Backdrop backdrop{{0.80f, 0.80f, 0.81f}, false, {0.66f, 0.66f, 0.67f}, 12};
  render::Sampling sampling = render::Sampling::kLinear;  // nearest: magnified pixel art stays crisp
};

// Times of the last frames, for the readouts' graph.
struct Timings {
  static constexpr size_t kHistory = 180;
  std::deque<float> frameMs;  // wall time between presented frames
  std::deque<float> solveMs;  // the shown frame's solve time
  double fps = 0;             // presented frames per second, smoothed
  void add(double frameSeconds, double solveMilliseconds);
};

// Edit mode's hold on the scrubber: the marks and the cuts' release markers are dragged in time
// (editor/editor_view.h installs the callbacks; empty: the scrubber only scrubs).
struct TimelineEditing {
  std::function<void(int mark)> selectMark;                        // a mark was clicked
  std::function<void(int mark, double time)> moveMark;             // a mark was dropped at `time` (s)
  std::function<void(const std::string& cut, int frame)> moveCut;  // a cut's marker was dropped on `frame`
  int selectedMark = -1;
  int draggedMark = -1;          // the mark being dragged, or -1
  std::string draggedCut;        // the cut whose marker is being dragged, or empty
  int draggedCutFrame = -1;      // the frame that marker was on
  double dragFrame = 0;          // where the dragged one is, in frames
  float pressX = 0;              // window px where it was picked up: a click that does not move changes nothing
  // Where the scrubber was drawn in the last frame (window px): frame f sits at
  // x0 + f / (frames - 1) * width; marks on the row at markY, cut markers on the row at cutY.
  float x0 = 0, width = 1, markY = 0, cutY = 0;
};

struct UiState {
  ViewSettings view;
  ViewNavigation navigation;
  Timings timings;
  PixelRect canvas;        // the part of the window the panels leave to the picture
  int width = 0, height = 0;  // window pixels
  bool weightsModeShown = false;  // weights mode was on last frame (its tab is brought forward once)
  bool screenshotRequested = false;
  bool closeRequested = false;  // Esc: the window closes
  std::string screenshotPath;  // where F12 writes; empty: inbetween-NNNN.png in the current folder
  int screenshots = 0;
  std::array<char, 64> typedValue{};  // a parameter's value being typed (the parameters panel's popup)
  std::function<void()> editPanel;  // edit mode: the Edit tab's contents (editor/editor_view.h); else empty
  TimelineEditing timelineEditing;
};

// The layout: a side panel on the right, the transport bar along the bottom.
constexpr float kSidePanelWidth = 340;
constexpr float kTransportHeight = 112;
PixelRect canvasRect(int width, int height);

void transportPanel(PlayerSession& session, UiState& ui);    // transport_panel.cpp: bottom bar, scrubber
void weightsPanel(PlayerSession& session);                   // weights_panel.cpp: sliders, triangle pad
void parametersPanel(PlayerSession& session, UiState& ui);   // parameters_panel.cpp: a control per live parameter
void viewPanel(PlayerSession& session, UiState& ui);         // view_panel.cpp: overlays, onion, backdrop, zoom
void readoutsPanel(PlayerSession& session, const UiState& ui);  // readouts_panel.cpp: fps, solve, graph
void filesPanel(PlayerSession& session, UiState& ui);        // files_panel.cpp: scene, reload, save, messages
void helpPanel();                                            // files_panel.cpp: the shortcuts
void messageBanner(PlayerSession& session, const UiState& ui);  // files_panel.cpp: the latest error
// The side panel: tabs holding the weights, parameters, view, files and help panels.
void sidePanel(PlayerSession& session, UiState& ui);         // view_panel.cpp
// Held pairs drawn over the picture (ImGui's background list), when asked for.
void heldPairMarks(const PlayerSession& session, const AnimationFrame& frame, const render::ViewBox& view,
                   const UiState& ui);                       // view_panel.cpp

}  // namespace ib::play
