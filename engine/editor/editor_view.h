// The editor in the player's window (`inbetween edit SCENE`, `inbetween new ...`): the keys side
// by side over the upper part of the canvas (more than fit: one large, the others as thumbnails
// a click shows large), each with its traced outline, its arcs coloured by
// the features they join, features with their names, cuts, interior features and painted
// stiffness, each view zoomed and panned on its own; the animation plays below, rebuilt in the
// background after every edit. Tools: features (click on the outline; drag along it), cuts
// (click points, double-click or Enter to end), interior features (press at the point, drag the
// radius), stiffness (brush strokes on the reference key). The Edit tab holds the tools, the
// selection, the keys and what to place next.
#pragma once

#include "editor/editor_session.h"
#include "editor/feature_suggestions.h"
#include "player/player_session.h"
#include "player/view_navigation.h"
#include "renderers/drawing_sheet.h"

#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ib::editor {

enum class Tool { kFeature, kCut, kInterior, kPaint };

// The tools' settings, declared once with their defaults.
struct ToolSettings {
  Tool tool = Tool::kFeature;
  int cutKind = 0;               // 0 notch, 1 split, 2 slit
  double snapScreenPixels = 12;  // window px: a click this close to the outline places a feature (any zoom)
  double brushRadius = 10;       // drawing px: a stiffness stroke's radius
  double brushKappa = 4;         // the stroke's stiffness (1 = the scene's; < 1 softer)
  bool erase = false;            // the brush removes the stroke under it instead
};

class EditorView {
 public:
  // Saves the player's parameters (its Save parameters button) into the document, then the file.
  EditorView(EditorSession& session, play::PlayerSession& player);
  ~EditorView();
  EditorView(const EditorView&) = delete;
  EditorView& operator=(const EditorView&) = delete;

  // Splits the canvas into the key views (top) and the animation's preview (below).
  void layout(const play::PixelRect& canvas, int width, int height);
  const play::PixelRect& preview() const { return preview_; }
  // The drawings to draw under the marks, one per key view.
  std::vector<render::SheetView> sheetViews() const;
  // The drawings of the keys, in key order; drawingsGeneration() changes when they do.
  const std::vector<RgbaImage>& drawings() const { return drawings_; }
  int drawingsGeneration() const { return drawingsGeneration_; }

  // Once per frame, before the panels: starts a background rebuild after a change, reads the
  // rebuild's outcome. Then input() (false: the pointer is not over a key view, the player may
  // use it) and marks() (drawn on ImGui's background list).
  void update();
  bool input();
  void marks();
  // The Edit tab's contents.
  void panel();
  // A key press for the editor (undo, redo, save, end a cut, delete); false: not the editor's.
  bool shortcut(int key, bool ctrl, bool shift);
  // The window title: the scene, with `*` while there are unsaved changes.
  std::string title() const;
  // The close button or Esc: true when the window may close now; with unsaved changes, asks first
  // (a dialog in the next frames) and returns false.
  bool mayClose();
  // The unsaved-changes dialog; true once the user chose to close.
  bool closeDialog();

  // The window presented a frame solved on the multimesh it plays now: the edit's latency is
  // measured here, once that multimesh is of the latest edit (or later).
  void newMeshPresented();
  // From an edit to the first frame drawn with the multimesh it started, ms (the latest; -1: none yet).
  double lastEditLatencyMs() const { return latencyMs_; }
  // Whether an edit's rebuild is still to be presented.
  bool awaitingFrame() const { return awaitingFrame_; }
  // The last failed build's message, until a build succeeds; empty when the last one did.
  const std::string& buildError() const { return buildError_; }
  EditorSession& session() { return session_; }
  // Proposes features at the corners every key's outline has (the Suggest button); then accept or
  // drop each in the Edit tab.
  void suggest();
  const std::vector<FeatureSuggestion>& suggestions() const { return suggestions_; }
  void acceptAll();
  // Added keys from dropped PNG files.
  void dropped(const std::vector<std::string>& paths);
  ToolSettings& tools() { return tools_; }
  // The scrubber in edit mode (play::TimelineEditing): a mark picked, a mark dropped at `time` (s),
  // a cut's marker dropped on `frame` (its release becomes the open keys' weight there).
  void selectMark(int mark);
  // An edit as the window's tools make it (timed for lastEditLatencyMs); InputError reported, not thrown.
  void apply(const edit::SceneEdit& edit) { run(edit); }
  const std::string& status() const { return status_; }  // the Edit tab's last message (a refused edit's)
  void moveMark(int mark, double time);
  void moveCut(const std::string& cut, int frame);
  int selectedMark() const { return selectedMark_; }

  // With more keys than fit side by side (views under 200 px wide), one key is shown large and the
  // others as thumbnails; a click on a thumbnail, or choosing the key in the Edit tab, shows it large.
  void focus(int key);
  int focusKey() const { return focusKey_; }
  bool thumbnailLayout() const;
  // Window pixel of key k's drawing point p, and the key's view (tests aim their clicks with it).
  Eigen::Vector2d toScreen(int key, const Eigen::Vector2d& p) const;
  // Window pixel of the centre of an Edit tab's control as last drawn (none before): the "Undo",
  // "Redo" and "Rename" buttons, the selection's "name" field, cut i's field "cut i" and its
  // button "cut i rename", key k's entry in the key list "key k".
  std::optional<Eigen::Vector2d> buttonCentre(const std::string& name) const {
    const auto it = buttons_.find(name);
    if (it == buttons_.end()) return std::nullopt;
    return Eigen::Vector2d((it->second.x0 + it->second.x1) / 2, (it->second.y0 + it->second.y1) / 2);
  }

 private:
  struct KeyView {
    play::PixelRect rect;
    play::ViewNavigation navigation;
    bool thumbnail = false;  // a small view: a click makes it the large one
  };
  render::ViewBox windowViewOf(int key) const;
  Eigen::Vector2d toDrawing(int key, double x, double y) const;
  double pixelsPerUnit(int key) const;  // window px per drawing px
  int viewUnder(double x, double y) const;
  void run(const edit::SceneEdit& edit);  // applies, or reports the message
  void run(const std::vector<edit::SceneEdit>& edits);  // all as one undo step, or none and the message
  void attempt(const std::function<void()>& change);     // runs a change of the document, or reports its InputError
  void report(const std::string& text, bool error);
  void loadDrawings();
  void featureInput(int key, const Eigen::Vector2d& p, bool pressed, bool held, bool released);
  void cutInput(int key, const Eigen::Vector2d& p, bool pressed, bool doubleClicked);
  void interiorInput(int key, const Eigen::Vector2d& p, bool pressed, bool released);
  void paintInput(int key, const Eigen::Vector2d& p, bool pressed, bool held, bool released);
  void finishCut();
  void keyMarks(int key);
  void keysPanel();
  void markPanel();
  void suggestionsPanel();
  void cutsPanel();
  void accept(size_t suggestion);
  void drawnAt(const std::string& control);  // records the last ImGui item's rectangle for buttonCentre

  EditorSession& session_;
  play::PlayerSession& player_;
  ToolSettings tools_;
  std::vector<KeyView> views_;
  play::PixelRect canvas_, preview_;
  int width_ = 1, height_ = 1;
  int focusKey_ = 0;  // the key shown large when there are thumbnails
  std::vector<RgbaImage> drawings_;
  std::vector<std::string> drawingFiles_;
  int drawingsGeneration_ = 0;

  // The selection and the gesture under way.
  int selectedKey_ = -1;
  std::string selected_;          // a feature of selectedKey_
  bool selectedInterior_ = false;
  bool dragging_ = false;
  bool draggingRadius_ = false;   // the Interior tool's drag of a disc's rim (dragAt_: its centre)
  Eigen::Vector2d dragAt_ = Eigen::Vector2d::Zero();
  int cutKey_ = -1;
  Polyline cutPoints_;
  int paintKey_ = -1;
  Polyline paintPoints_;
  int lastEditedKey_ = -1;
  int selectedMark_ = -1;
  std::vector<FeatureSuggestion> suggestions_;  // proposed by Suggest, until accepted or dropped
  std::array<char, 512> drawingBuffer_{};  // another drawing for the selected key
  std::vector<std::pair<std::string, std::array<char, 64>>> cutNames_;  // the Cuts list's fields: the name each shows, its text
  int hoverKey_ = -1;
  Eigen::Vector2d hover_ = Eigen::Vector2d::Zero();
  std::array<char, 64> renameBuffer_{};
  std::array<char, 512> addKeyBuffer_{};

  // Rebuilds: the generation sent, when, and whether the optimized build followed.
  int sentGeneration_ = -1;
  bool optimizedSent_ = true;
  std::chrono::steady_clock::time_point editTime_{};
  bool awaitingFrame_ = false;
  int expectedBuild_ = 0;  // the reloader's request of the last edit's quick build
  double latencyMs_ = -1;
  std::string status_;
  bool statusError_ = false;
  std::map<std::string, play::PixelRect> buttons_;  // buttonCentre's, by label
  std::string buildError_;
  size_t messagesRead_ = 0;  // of the player's messages
  bool closeAsked_ = false;
};

}  // namespace ib::editor
