// Dear ImGui on the window presenter: one ImGui context (owned here, never global state of ours),
// its GLFW input backend and its Vulkan backend drawing into the presenter's render pass after the
// mesh. beginFrame() starts a UI frame, overlay() ends it and returns what present() records.
#pragma once

#include "renderers/window_presenter.h"

struct ImGuiContext;

namespace ib::play {

class ImGuiLayer {
 public:
  // Installs ImGui's GLFW callbacks on the presenter's window (they chain to earlier ones) and
  // uploads the font atlas. `userData` is left in ImGuiIO::UserData for the window's own GLFW
  // callbacks (a dropped file). Throws VulkanError.
  ImGuiLayer(render::WindowPresenter& presenter, void* userData);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void beginFrame();
  // Ends the UI frame (ImGui::Render) and returns the overlay that draws it.
  render::Overlay endFrame();
  // Ends the UI frame without drawing it (a layout pass).
  void skipFrame();

 private:
  void shutdown();  // the backends that started, then the context
  ImGuiContext* context_ = nullptr;
  bool glfw_ = false, vulkan_ = false;  // which backends are up, for the destructor
};

// The player's look: a dark theme with rounded corners and the accent of a real tool.
void applyPlayerStyle();

}  // namespace ib::play
