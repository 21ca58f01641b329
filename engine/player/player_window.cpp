#include "player/player_window.h"

#include "core/error.h"
#include "editor/editor_view.h"
#include "pipeline/artwork_sampling.h"
#include "player/shortcuts.h"
#include "gpu/vulkan_check.h"

#include <imgui.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>

namespace ib::play {

namespace {

render::WindowOptions presenterOptions(const PlayerWindowOptions& options, const std::string& scenePath) {
  render::WindowOptions out;
  out.window = {options.width, options.height, "inbetween play - " + scenePath, true};
  out.vsync = options.vsync;
  out.samples = options.samples;
  out.validation = options.validation;
  out.device = options.device;
  return out;
}

void onDrop(GLFWwindow*, int count, const char** paths) {
  auto* window = static_cast<PlayerWindow*>(ImGui::GetIO().UserData);
  if (window) window->dropped(std::vector<std::string>(paths, paths + count));
}

void onKey(GLFWwindow* glfwWindow, int key, int scancode, int action, int mods) {
  auto* window = static_cast<PlayerWindow*>(ImGui::GetIO().UserData);
  if (window) window->keyEvent(glfwWindow, key, scancode, action, mods);
}

// Whether `button` was held down through the frame before too: not pressed just now.
bool heldSinceLastFrame(ImGuiMouseButton button) { return ImGui::IsMouseDown(button) && !ImGui::IsMouseClicked(button); }

}  // namespace

PlayerWindow::PlayerWindow(PlayerSession& session, const PlayerWindowOptions& options) : session_(session) {
  presenter_ = std::make_unique<render::WindowPresenter>(session.renderMesh(), presenterOptions(options, session.scenePath()));
  imgui_ = std::make_unique<ImGuiLayer>(*presenter_, this);
  glfwSetDropCallback(presenter_->window().get(), &onDrop);
  // After ImGui's: ours passes every key event on to ImGui's callback, then queues the presses.
  previousKey_ = glfwSetKeyCallback(presenter_->window().get(), &onKey);
  last_ = std::chrono::steady_clock::now();
  samplingOverride_ = options.sampling;
  applySceneSampling(true);
  if (options.editor) {
    editor_ = std::make_unique<editor::EditorView>(*options.editor, session);
    ui_.editPanel = [this] { editor_->panel(); };
    ui_.timelineEditing.selectMark = [this](int mark) { editor_->selectMark(mark); };
    ui_.timelineEditing.moveMark = [this](int mark, double time) { editor_->moveMark(mark, time); };
    ui_.timelineEditing.moveCut = [this](const std::string& cut, int frame) { editor_->moveCut(cut, frame); };
    sheetPool_ = vk::createCommandPool(presenter_->context());
    presenter_->window().setTitle(editor_->title());
  }
}

void PlayerWindow::updateSheet() {
  if (!editor_ || editor_->drawingsGeneration() == sheetGeneration_) return;
  presenter_->waitIdle();  // the old sheet's texture may be in a frame in flight
  sheet_.reset();
  const render::OverlayTarget target = presenter_->overlayTarget();
  try {
    if (!editor_->drawings().empty())
      sheet_ = std::make_unique<render::DrawingSheet>(presenter_->context(), sheetPool_.get(), editor_->drawings(),
                                                       target.renderPass, target.samples);
  } catch (const std::exception& e) {  // a drawing larger than the device's images: the views stay empty
    session_.messages().push_back({std::string("cannot show the drawings: ") + e.what(), true});
  }
  sheetGeneration_ = editor_->drawingsGeneration();
}

bool PlayerWindow::closing() {
  if (!editor_ || closeConfirmed_) return true;
  return editor_->mayClose();
}

void PlayerWindow::applySceneSampling(bool force) {
  const bool nearest = nearestSampling(session_.scene().scene, session_.scene().drawings);
  if (!force && nearest == sceneNearest_) return;
  sceneNearest_ = nearest;
  ui_.view.sampling = samplingOverride_.value_or(nearest ? render::Sampling::kNearest : render::Sampling::kLinear);
}

PlayerWindow::~PlayerWindow() {
  editor_.reset();
  glfwSetDropCallback(presenter_->window().get(), nullptr);
  glfwSetKeyCallback(presenter_->window().get(), previousKey_);  // ImGui's again, for its shutdown
  // The UI's buffers and pipeline go before the presenter's device, once no frame uses them.
  try {
    presenter_->waitIdle();
  } catch (const vk::VulkanError&) {  // a lost device runs nothing any more: destroying is safe
  }
  imgui_.reset();
  sheet_.reset();
}

void PlayerWindow::dropped(const std::vector<std::string>& paths) {
  if (editor_) dropped_.insert(dropped_.end(), paths.begin(), paths.end());  // drawings: new keys
  else if (!paths.empty()) dropped_.push_back(paths.front());
}

void PlayerWindow::keyEvent(GLFWwindow* window, int key, int scancode, int action, int mods) {
  if (keys_.record({key, scancode, action, mods}) && previousKey_) previousKey_(window, key, scancode, action, mods);
}

bool PlayerWindow::shouldClose() const { return presenter_->window().shouldClose(); }

void PlayerWindow::run() {
  while (!shouldClose())
    if (!frame() && presenter_->window().framebufferSize().width == 0) vk::pollWindowEvents(true);  // minimized: sleep
}

render::ViewBox PlayerWindow::contentBox() const {
  double w = 1, h = 1;
  for (const RgbaImage& d : session_.scene().drawings) {
    w = std::max(w, double(d.width));
    h = std::max(h, double(d.height));
  }
  return {0, 0, w, h};
}

void PlayerWindow::handleInput(const render::ViewBox& content) {
  const ImGuiIO& io = ImGui::GetIO();
  // Shortcuts unless a text field has the keyboard (its keys are text, and dropped here): every
  // press since the last frame in order, however short, repeating at the system's key repeat.
  for (const KeyPress& press : keys_.take())
    if (!io.WantTextInput && !(editor_ && editor_->shortcut(press.key, press.ctrl, press.shift)))
      applyShortcut(press.key, press.ctrl, session_, ui_);
  if (ui_.closeRequested) {
    ui_.closeRequested = false;
    if (closing()) glfwSetWindowShouldClose(presenter_->window().get(), GLFW_TRUE);
  }
  if (editor_ && editor_->input()) return;  // the pointer is over a key: the editor's
  const PixelRect& picture = ui_.canvas;
  if (io.WantCaptureMouse || !picture.contains(io.MousePos.x, io.MousePos.y)) return;
  if (io.MouseWheel != 0)
    ui_.navigation.zoomAt(std::pow(1.15, io.MouseWheel), io.MousePos.x, io.MousePos.y, content, picture, ui_.width,
                          ui_.height);
  // The picture follows the pointer while a button is held. Not on the frame the button goes
  // down: the pointer's move since the last frame came before the press (a click would jump).
  if (heldSinceLastFrame(ImGuiMouseButton_Left) || heldSinceLastFrame(ImGuiMouseButton_Middle))
    ui_.navigation.drag(io.MouseDelta.x, io.MouseDelta.y, content, picture, ui_.width, ui_.height);
}

void PlayerWindow::panels() {
  sidePanel(session_, ui_);
  transportPanel(session_, ui_);
  readoutsPanel(session_, ui_);
  messageBanner(session_, ui_);
  if (editor_) {
    editor_->marks();
    if (editor_->closeDialog()) {
      closeConfirmed_ = true;
      glfwSetWindowShouldClose(presenter_->window().get(), GLFW_TRUE);
    }
  }
}

bool PlayerWindow::frame(RgbaImage* capture) {
  // Releases held back from the frame before reach ImGui first, then this frame's events.
  for (const KeyEvent& e : keys_.nextFrame())
    if (previousKey_) previousKey_(presenter_->window().get(), e.key, e.scancode, e.action, e.mods);
  vk::pollWindowEvents();
  if (presenter_->window().shouldClose() && !closing())  // the close button with unsaved edits: ask first
    glfwSetWindowShouldClose(presenter_->window().get(), GLFW_FALSE);
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - last_).count();
  last_ = now;
  if (editor_ && !dropped_.empty()) editor_->dropped(dropped_);
  for (const std::string& path : editor_ ? std::vector<std::string>{} : dropped_) {
    try {
      session_.reloader().open(path);
      session_.messages().push_back({"opening " + path, false});
    } catch (const InputError& e) {
      session_.messages().push_back({e.what(), true});
    }
  }
  dropped_.clear();
  if (editor_) {
    editor_->update();
    ui_.timelineEditing.selectedMark = editor_->selectedMark();
  }
  if (session_.update(seconds)) {
    presenter_->prepareMesh(session_.renderMesh());  // drawn from the new multimesh's first solved frame on
    meshPending_ = true;
    applySceneSampling(false);
    if (!editor_) presenter_->window().setTitle("inbetween play - " + session_.scenePath());
  }
  if (editor_) {
    if (editor_->title() != title_) presenter_->window().setTitle(title_ = editor_->title());
  }

  const VkExtent2D size = presenter_->window().framebufferSize();
  ui_.width = static_cast<int>(std::max(1u, size.width));
  ui_.height = static_cast<int>(std::max(1u, size.height));
  ui_.canvas = canvasRect(ui_.width, ui_.height);
  if (editor_) {  // the keys above; the animation, its readouts and messages below them
    editor_->layout(ui_.canvas, ui_.width, ui_.height);
    ui_.canvas = editor_->preview();
  }
  const render::ViewBox content = contentBox();
  // ImGui sizes auto-fitted windows and tab bars from the frame before: the first frame is laid
  // out twice without being drawn, so even a one-frame screenshot shows every panel.
  for (int pass = laidOut_ ? 0 : 2; pass > 0; --pass) {
    imgui_->beginFrame();
    panels();
    imgui_->skipFrame();
  }
  laidOut_ = true;
  imgui_->beginFrame();
  handleInput(content);
  panels();

  // What to draw: the shown frame, with its solved neighbours as onion skins on the timeline.
  const std::shared_ptr<const AnimationFrame> shown = session_.shown();
  const render::ViewBox view =
      ui_.navigation.windowView(content, ui_.canvas, ui_.width, ui_.height);
  // A reloaded multimesh is drawn once its worker has solved a frame; until then the last frame
  // of the one before stays on screen (without onion skins), not an empty canvas.
  if (meshPending_ && shown && shown->x.rows() == session_.renderMesh().vertexCount) {
    presenter_->usePreparedMesh();
    meshPending_ = false;
  }
  std::deque<AnimationFrame> window;
  size_t at = 0;
  render::FrameDraw draw;
  draw.view = view;
  draw.overlays = ui_.view.overlays;
  if (meshPending_ && lastDrawn_) {
    window.push_back(*lastDrawn_);
    render::OnionStyle style = ui_.view.onion;
    style.neighbours = 0;
    draw = render::frameWithOnionSkins(window, 0, style, view, ui_.view.overlays);
  } else if (!meshPending_ && shown && shown->x.rows() == session_.renderMesh().vertexCount) {
    lastDrawn_ = shown;
    const int n = session_.weightsMode() ? 0 : ui_.view.onion.neighbours;
    for (int d = n; d >= 1; --d)
      if (auto f = session_.cachedFrame(shown->index - d)) window.push_back(*f);
    at = window.size();
    window.push_back(*shown);
    for (int d = 1; d <= n; ++d)
      if (auto f = session_.cachedFrame(shown->index + d)) window.push_back(*f);
    render::OnionStyle style = ui_.view.onion;
    style.neighbours = n;
    draw = render::frameWithOnionSkins(window, at, style, view, ui_.view.overlays);
    heldPairMarks(session_, window[at], view, ui_);
  }
  draw.sampling = ui_.view.sampling;
  presenter_->setBackdrop(ui_.view.backdrop);
  render::Overlay overlay = imgui_->endFrame();
  updateSheet();  // after the panels: this frame's edits may have changed the keys
  if (editor_ && sheet_) {  // the keys over the animation's upper part, the UI over both
    const std::vector<render::SheetView> views = editor_->sheetViews();
    const VkExtent2D extent = presenter_->extent();
    const render::Sampling sampling = ui_.view.sampling;
    overlay = [this, views, extent, sampling, ui = std::move(overlay)](VkCommandBuffer cmd) {
      sheet_->record(cmd, extent, views, sampling);
      if (ui) ui(cmd);
    };
  }
  RgbaImage shot;
  const bool wantShot = ui_.screenshotRequested && presenter_->canCapture();
  const bool presented = presenter_->present(draw, overlay, capture ? capture : wantShot ? &shot : nullptr);
  if (presented && editor_ && editor_->awaitingFrame() && !meshPending_ && shown &&
      shown->x.rows() == session_.renderMesh().vertexCount)
    editor_->newMeshPresented();
  if (presented && wantShot) {
    ui_.screenshotRequested = false;
    writeScreenshot(capture ? *capture : shot);
  }
  if (laidOutFrames_++ > 0) ui_.timings.add(seconds, shown ? shown->milliseconds : 0);  // the first follows the load
  return presented;
}

void PlayerWindow::writeScreenshot(const RgbaImage& image) {
  std::string path = ui_.screenshotPath;
  if (path.empty()) {
    char name[48];
    std::snprintf(name, sizeof name, "inbetween-%04d.png", ++ui_.screenshots);
    path = name;
  }
  try {
    writePng(path, image);
    session_.messages().push_back({"wrote " + path, false});
  } catch (const InputError& e) {
    session_.messages().push_back({e.what(), true});
  }
}

}  // namespace ib::play
