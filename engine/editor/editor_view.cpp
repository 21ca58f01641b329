#include "editor/editor_view.h"

#include "core/error.h"
#include "pipeline/cut_timing.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace ib::editor {

namespace {

constexpr double kPreviewShare = 0.36;   // of the canvas's height: the animation below the keys
constexpr double kIdleBeforeOptimizing = 1.5;  // s without an edit before the Comesh-optimized rebuild
constexpr double kMinViewWidth = 200;    // window px: narrower key views side by side give way to one large view and thumbnails
constexpr double kFocusShare = 0.5;      // of the canvas's width: the large view's, with thumbnails

}  // namespace

EditorView::EditorView(EditorSession& session, play::PlayerSession& player) : session_(session), player_(player) {
  loadDrawings();
  sentGeneration_ = session_.generation();  // the player built the scene as opened
  for (int k = 0; k < session_.keyCount(); ++k)
    if (session_.marks().keys[static_cast<size_t>(k)].name == session_.marks().reference) focusKey_ = k;
  // The live parameters go into the document (one undoable edit), and the document into the
  // file: the file never gets ahead of the document, which a later save would write back.
  player_.setParameterSaver([this](play::LiveParameters& parameters, double fps) {
    std::vector<edit::SceneEdit> edits = parameters.saveEdits(session_.document());
    if (session_.document().parameter("fps") != fps) edits.push_back(edit::SetParameter{"fps", fps});
    session_.applyAll(edits);  // one undo step; none of them when one fails
    parameters.markSaved();
    session_.save();
  });
}

EditorView::~EditorView() { player_.setParameterSaver(nullptr); }

void EditorView::loadDrawings() {
  std::vector<std::string> files;
  for (int k = 0; k < session_.keyCount(); ++k) files.push_back(session_.drawingPath(k));
  if (files == drawingFiles_) return;
  std::vector<RgbaImage> drawings;
  for (const std::string& file : files) {
    try {
      drawings.push_back(readPng(file));
    } catch (const InputError& e) {
      report(e.what(), true);
      RgbaImage blank;  // the key's view stays, empty, with the message
      blank.width = blank.height = 1;
      blank.pixels.assign(4, 0);
      drawings.push_back(blank);
    }
  }
  drawings_ = std::move(drawings);
  drawingFiles_ = files;
  views_.resize(files.size());
  ++drawingsGeneration_;
}

void EditorView::layout(const play::PixelRect& canvas, int width, int height) {
  canvas_ = canvas;
  width_ = width;
  height_ = height;
  const double split = canvas.y1 - (canvas.y1 - canvas.y0) * kPreviewShare;
  preview_ = {canvas.x0, split, canvas.x1, canvas.y1};
  const int m = static_cast<int>(views_.size());
  const double across = canvas.x1 - canvas.x0, down = split - canvas.y0;
  const auto place = [&](int k, double x0, double y0, double x1, double y1, bool thumbnail) {
    KeyView& v = views_[static_cast<size_t>(k)];
    v.rect = {x0 + 2, y0 + 2, x1 - 2, y1 - 2};
    v.thumbnail = thumbnail;
  };
  if (m * kMinViewWidth <= across) {  // side by side
    for (int k = 0; k < m; ++k) place(k, canvas.x0 + k * across / m, canvas.y0, canvas.x0 + (k + 1) * across / m, split - 2, false);
    return;
  }
  // One key large on the left; the others as thumbnails in a grid on the right, its columns
  // chosen for the largest cells (the drawings' shape unknown: their smaller side counts).
  focusKey_ = std::clamp(focusKey_, 0, m - 1);
  const double focusWidth = std::max(kMinViewWidth, across * kFocusShare);
  place(focusKey_, canvas.x0, canvas.y0, canvas.x0 + focusWidth, split - 2, false);
  const int n = m - 1;
  const double gridWidth = across - focusWidth;
  int columns = 1;
  const auto cell = [&](int c) { return std::min(gridWidth / c, down / ((n + c - 1) / c)); };
  for (int c = 2; c <= n; ++c)
    if (cell(c) > cell(columns)) columns = c;
  const double cellWidth = gridWidth / columns, cellHeight = down / ((n + columns - 1) / columns);
  for (int k = 0, i = 0; k < m; ++k) {
    if (k == focusKey_) continue;
    const double x0 = canvas.x0 + focusWidth + (i % columns) * cellWidth, y0 = canvas.y0 + (i / columns) * cellHeight;
    place(k, x0, y0, x0 + cellWidth, y0 + cellHeight, true);
    ++i;
  }
}

bool EditorView::thumbnailLayout() const {
  return std::any_of(views_.begin(), views_.end(), [](const KeyView& v) { return v.thumbnail; });
}

void EditorView::focus(int key) {
  if (key >= 0 && key < static_cast<int>(views_.size())) focusKey_ = key;
}

render::ViewBox EditorView::windowViewOf(int key) const {
  const RgbaImage& d = drawings_[static_cast<size_t>(key)];
  const KeyView& v = views_[static_cast<size_t>(key)];
  return v.navigation.windowView({0, 0, double(d.width), double(d.height)}, v.rect, width_, height_);
}

double EditorView::pixelsPerUnit(int key) const {
  const render::ViewBox view = windowViewOf(key);
  return width_ / (view.x1 - view.x0);
}

Eigen::Vector2d EditorView::toDrawing(int key, double x, double y) const {
  const render::ViewBox view = windowViewOf(key);
  return {view.x0 + x / width_ * (view.x1 - view.x0), view.y0 + y / height_ * (view.y1 - view.y0)};
}

Eigen::Vector2d EditorView::toScreen(int key, const Eigen::Vector2d& p) const { return play::toWindow(windowViewOf(key), width_, height_, p); }

int EditorView::viewUnder(double x, double y) const {
  for (int k = 0; k < static_cast<int>(views_.size()); ++k)
    if (views_[static_cast<size_t>(k)].rect.contains(x, y)) return k;
  return -1;
}

std::vector<render::SheetView> EditorView::sheetViews() const {
  std::vector<render::SheetView> out;
  for (int k = 0; k < static_cast<int>(views_.size()); ++k) {
    const play::PixelRect& r = views_[static_cast<size_t>(k)].rect;
    render::SheetView v;
    v.key = k;
    v.view = windowViewOf(k);
    v.scissor = {static_cast<int>(r.x0), static_cast<int>(r.y0), static_cast<int>(r.x1 - r.x0), static_cast<int>(r.y1 - r.y0)};
    v.background = k == hoverKey_ ? std::array<float, 4>{0.86f, 0.86f, 0.87f, 1} : std::array<float, 4>{0.82f, 0.82f, 0.83f, 1};
    out.push_back(v);
  }
  return out;
}

void EditorView::report(const std::string& text, bool error) {
  status_ = text;
  statusError_ = error;
  player_.messages().push_back({text, error});
}

void EditorView::run(const edit::SceneEdit& edit) { attempt([&] { session_.apply(edit); }); }

void EditorView::run(const std::vector<edit::SceneEdit>& edits) { attempt([&] { session_.applyAll(edits); }); }

void EditorView::attempt(const std::function<void()>& change) {
  try {
    change();
    status_.clear();
    editTime_ = std::chrono::steady_clock::now();
  } catch (const InputError& e) {
    report(e.what(), true);
  }
}

void EditorView::update() {
  loadDrawings();
  // Suggestions are per key index: a change of the keys makes them stale.
  if (!suggestions_.empty() && suggestions_.front().at.size() != static_cast<size_t>(session_.keyCount())) suggestions_.clear();
  // A selection the document no longer has (undone, renamed, removed) goes.
  if (selectedKey_ >= session_.keyCount()) selectedKey_ = -1, selected_.clear();
  if (selectedKey_ >= 0 && !selected_.empty() && !dragging_) {
    const KeyMarks& k = session_.marks().keys[static_cast<size_t>(selectedKey_)];
    if (!(selectedInterior_ ? k.interior.count(selected_) : k.features.count(selected_))) selected_.clear();
  }
  // A change: the initial map at once (tens of ms), the optimized multimesh once the edits pause.
  const SceneDocument& doc = session_.document();
  const auto now = std::chrono::steady_clock::now();
  if (session_.generation() != sentGeneration_) {
    sentGeneration_ = session_.generation();
    if (!doc.problem()) {
      expectedBuild_ = player_.reloader().rebuildFromText(doc.text(), false);
      optimizedSent_ = false;
      awaitingFrame_ = true;
      buildError_.clear();
    }
  } else if (!optimizedSent_ && !doc.problem() && !player_.reloader().busy() &&
             std::chrono::duration<double>(now - editTime_).count() > kIdleBeforeOptimizing) {
    player_.reloader().rebuildFromText(doc.text(), true);
    optimizedSent_ = true;
  }
  // The player's messages since the last look: a failed build's names what to fix; a good one clears it.
  const std::vector<play::PlayerSession::Message>& messages = player_.messages();
  for (size_t i = std::min(messagesRead_, messages.size()); i < messages.size(); ++i) {
    if (messages[i].error && messages[i].text.rfind("reload failed: ", 0) == 0) buildError_ = messages[i].text.substr(15);
    if (!messages[i].error && messages[i].text.rfind("reloaded ", 0) == 0) buildError_.clear();
  }
  messagesRead_ = messages.size();
}

bool EditorView::input() {
  loadDrawings();  // a shortcut just before (undo) may have changed the keys
  const ImGuiIO& io = ImGui::GetIO();
  hoverKey_ = io.WantCaptureMouse ? -1 : viewUnder(io.MousePos.x, io.MousePos.y);
  // A gesture stays with its view until the button is released, wherever the pointer goes.
  int key = hoverKey_;
  if (dragging_ && selectedKey_ >= 0) key = selectedKey_;
  if (paintKey_ >= 0 && ImGui::IsMouseDown(ImGuiMouseButton_Left)) key = paintKey_;
  if (key < 0 || key >= static_cast<int>(views_.size())) return false;
  KeyView& view = views_[static_cast<size_t>(key)];
  if (view.thumbnail) {  // a thumbnail is a button: it shows its key large, and takes no edits
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) focus(key);
    return true;
  }
  const RgbaImage& d = drawings_[static_cast<size_t>(key)];
  const render::ViewBox content{0, 0, double(d.width), double(d.height)};
  hover_ = toDrawing(key, io.MousePos.x, io.MousePos.y);
  if (io.MouseWheel != 0) view.navigation.zoomAt(std::pow(1.15, io.MouseWheel), io.MousePos.x, io.MousePos.y, content, view.rect, width_, height_);
  if ((ImGui::IsMouseDown(ImGuiMouseButton_Right) && !ImGui::IsMouseClicked(ImGuiMouseButton_Right)) ||
      (ImGui::IsMouseDown(ImGuiMouseButton_Middle) && !ImGui::IsMouseClicked(ImGuiMouseButton_Middle)))
    view.navigation.drag(io.MouseDelta.x, io.MouseDelta.y, content, view.rect, width_, height_);
  const bool pressed = ImGui::IsMouseClicked(ImGuiMouseButton_Left);
  const bool held = ImGui::IsMouseDown(ImGuiMouseButton_Left) && !pressed;
  const bool released = ImGui::IsMouseReleased(ImGuiMouseButton_Left);
  switch (tools_.tool) {
    case Tool::kFeature: featureInput(key, hover_, pressed, held, released); break;
    case Tool::kCut: cutInput(key, hover_, pressed, ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)); break;
    case Tool::kInterior: interiorInput(key, hover_, pressed, released); break;
    case Tool::kPaint: paintInput(key, hover_, pressed, held, released); break;
  }
  return true;
}

bool EditorView::shortcut(int key, bool ctrl, bool shift) {
  constexpr int kZ = 90, kS = 83, kEnter = 257, kKeypadEnter = 335, kDelete = 261, kBackspace = 259, kEscape = 256;
  if (ctrl && key == kZ) {
    if (shift) session_.redo();
    else session_.undo();
    editTime_ = std::chrono::steady_clock::now();
    dragging_ = draggingRadius_ = false;
    return true;
  }
  if (ctrl && key == kS) {
    try {
      session_.save();
      report("saved " + session_.document().path(), false);
    } catch (const InputError& e) {
      report(e.what(), true);
    }
    return true;
  }
  if (ctrl) return false;
  constexpr int kQ = 81, kC = 67, kD = 68, kB = 66;  // the tools
  if (key == kQ || key == kC || key == kD || key == kB) {
    tools_.tool = key == kQ ? Tool::kFeature : key == kC ? Tool::kCut : key == kD ? Tool::kInterior : Tool::kPaint;
    return true;
  }
  if ((key == kEnter || key == kKeypadEnter) && cutKey_ >= 0) {
    finishCut();
    return true;
  }
  if (key == kEscape && (cutKey_ >= 0 || paintKey_ >= 0)) {
    cutKey_ = paintKey_ = -1;
    cutPoints_.clear();
    paintPoints_.clear();
    return true;
  }
  if ((key == kDelete || key == kBackspace) && selectedKey_ >= 0 && !selected_.empty()) {
    const std::string keyName = shift ? "" : session_.marks().keys[static_cast<size_t>(selectedKey_)].name;
    if (selectedInterior_) run(edit::RemoveInteriorFeature{selected_, keyName});
    else run(edit::RemoveFeature{selected_, keyName});
    selected_.clear();
    return true;
  }
  return false;
}

void EditorView::suggest() {
  std::vector<std::vector<Outline>> outlines;
  for (int k = 0; k < session_.keyCount(); ++k) outlines.push_back(session_.outlines(k));
  // Once features are placed, what the shape matching pairs between them; before (or when the
  // keys' features do not match up yet), corners every key has.
  try {
    suggestions_ = matchedSuggestions(session_.document().scene(), outlines);
  } catch (const InputError&) {
    suggestions_.clear();
  }
  if (!suggestions_.empty()) {
    report(std::to_string(suggestions_.size()) + " features suggested where the shape matching pairs the outlines' corners", false);
    return;
  }
  suggestions_ = suggestFeatures(session_.marks(), outlines);
  report(suggestions_.empty() ? "no corners found that every key has" : std::to_string(suggestions_.size()) + " features suggested at corners every key has",
         false);
}

void EditorView::accept(size_t suggestion) {
  const FeatureSuggestion s = suggestions_.at(suggestion);
  suggestions_.erase(suggestions_.begin() + static_cast<std::ptrdiff_t>(suggestion));
  const std::string name = session_.freshName("corner");
  std::vector<edit::SceneEdit> edits;  // the feature in every key: one undo step
  for (int k = 0; k < session_.keyCount() && k < static_cast<int>(s.at.size()); ++k)
    edits.push_back(edit::SetFeature{session_.marks().keys[static_cast<size_t>(k)].name, name, s.at[static_cast<size_t>(k)]});
  run(edits);
}

void EditorView::acceptAll() {
  while (!suggestions_.empty()) accept(0);
}

void EditorView::selectMark(int mark) { selectedMark_ = mark; }

void EditorView::moveMark(int mark, double time) {
  selectedMark_ = mark;
  run(edit::MoveMark{mark, time});
}

void EditorView::moveCut(const std::string& cut, int frame) {
  // The open keys' weight at that frame, kept off 0 and 1 (where the cut would never let go).
  const double release = std::clamp(openWeight(player_.scene().scene, cut, frame), 0.02, 0.98);
  run(edit::SetCutRelease{cut, std::round(release * 1000) / 1000});
}

void EditorView::newMeshPresented() {
  if (!awaitingFrame_ || session_.generation() != sentGeneration_ || player_.scene().build < expectedBuild_) return;
  awaitingFrame_ = false;
  latencyMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - editTime_).count();
}

std::string EditorView::title() const {
  return "inbetween edit - " + session_.document().path() + (session_.document().modified() ? " *" : "");
}

bool EditorView::mayClose() {
  if (!session_.document().modified()) return true;
  closeAsked_ = true;
  return false;
}

void EditorView::dropped(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    const std::filesystem::path file(path);
    if (file.extension() != ".png" && file.extension() != ".PNG") {
      report(path + ": drop PNG drawings to add them as keys", true);
      continue;
    }
    const std::filesystem::path folder = std::filesystem::absolute(session_.document().path()).parent_path();
    run(edit::AddKey{file.stem().string(), std::filesystem::relative(std::filesystem::absolute(file), folder).generic_string()});
  }
}

}  // namespace ib::editor
