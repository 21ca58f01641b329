// The player's window: the presenter (GLFW + Vulkan), the Dear ImGui layer and the input, over a
// PlayerSession. Each frame() polls events, updates the session (never waiting for a solve),
// draws the shown frame with the panels over it and presents; frame(capture) also reads the
// window back, UI included.
#pragma once

#include "player/imgui_layer.h"
#include "player/key_queue.h"
#include "player/player_session.h"
#include "player/player_ui.h"
#include "gpu/gpu_resources.h"
#include "renderers/drawing_sheet.h"
#include "renderers/window_presenter.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace ib::editor {
class EditorSession;
class EditorView;
}  // namespace ib::editor

namespace ib::play {

struct PlayerWindowOptions {
  int width = 1280, height = 720;  // window pixels
  bool vsync = true;
  // MSAA samples, lowered to what the device offers. 2, not render's 4: on lavapipe at 1280x720
  // 4x took the player from 60 to 27 presented frames per second (bench play, square-arch-notch).
  int samples = 2;
  bool validation = false;         // Khronos validation layer; messages via context()
  vk::DevicePreference device = vk::DevicePreference::kAny;
  // The artwork's filtering at the start and after every reload (the View panel can change it):
  // this when given (--sampling), else the scene's "sampling" (pipeline/artwork_sampling.h).
  std::optional<render::Sampling> sampling;
  // The editor (`inbetween edit`): its keys above the animation, its Edit tab, its shortcuts; the
  // session must outlive the window. Default null: the player alone.
  editor::EditorSession* editor = nullptr;
};

class PlayerWindow {
 public:
  // Opens the window on the session's scene. Throws vk::WindowError (no display) or
  // vk::VulkanError (no device that presents to it). The session must outlive the window.
  PlayerWindow(PlayerSession& session, const PlayerWindowOptions& options);
  ~PlayerWindow();
  PlayerWindow(const PlayerWindow&) = delete;
  PlayerWindow& operator=(const PlayerWindow&) = delete;

  // One frame. With `capture`, the presented window is copied into it. Returns false when the
  // frame was skipped (minimized, or the swapchain was rebuilt).
  bool frame(RgbaImage* capture = nullptr);
  bool shouldClose() const;
  void run();  // frames until the window is closed (Esc or the window's close button)

  UiState& ui() { return ui_; }
  // The editor's view when editing, else null.
  editor::EditorView* editor() { return editor_.get(); }
  const vk::VulkanContext& context() const { return presenter_->context(); }
  // Called by GLFW's drop callback: the first dropped file opens (in the next frame).
  void dropped(const std::vector<std::string>& paths);
  // Called by GLFW's key callback: queues a press for the shortcuts of the next frame and passes
  // the event on to the callback installed before (Dear ImGui's), a quick tap's release a frame
  // later (KeyQueue).
  void keyEvent(GLFWwindow* window, int key, int scancode, int action, int mods);

 private:
  void handleInput(const render::ViewBox& content);
  void panels();  // every panel, once per UI frame
  render::ViewBox contentBox() const;  // the drawings' canvas, drawing pixels
  void writeScreenshot(const RgbaImage& image);
  // The View panel's sampling from the override or the scene, when the scene's choice is new (a
  // reload that keeps it keeps what the user set in the panel).
  void applySceneSampling(bool force);
  // Edit mode: the drawing sheet of the editor's current drawings (made again when they change).
  void updateSheet();
  bool closing();  // the window's close was asked for and may go ahead (the editor asks to save first)

  PlayerSession& session_;
  std::unique_ptr<render::WindowPresenter> presenter_;
  std::unique_ptr<ImGuiLayer> imgui_;
  UiState ui_;
  std::chrono::steady_clock::time_point last_;
  std::vector<std::string> dropped_;
  KeyQueue keys_;  // presses since the last frame, for the shortcuts; releases held back for ImGui
  void (*previousKey_)(GLFWwindow*, int, int, int, int) = nullptr;  // GLFW's key callback before ours
  bool laidOut_ = false;  // the first frame's layout passes are done
  bool meshPending_ = false;  // the session reloaded its multimesh; the presenter draws the old one
  std::shared_ptr<const AnimationFrame> lastDrawn_;  // the frame drawn last, of the presenter's mesh
  int laidOutFrames_ = 0;  // frames presented or skipped so far
  std::optional<render::Sampling> samplingOverride_;  // PlayerWindowOptions::sampling
  bool sceneNearest_ = false;                        // the scene's sampling last applied: nearest
  std::unique_ptr<editor::EditorView> editor_;       // edit mode
  vk::CommandPoolObject sheetPool_;                  // uploads of the drawing sheet
  std::unique_ptr<render::DrawingSheet> sheet_;
  int sheetGeneration_ = -1;                         // the editor's drawings the sheet holds
  bool closeConfirmed_ = false;                      // the editor's unsaved-changes dialog said close
  std::string title_;                                // the window's title as last set (edit mode)
};

}  // namespace ib::play
