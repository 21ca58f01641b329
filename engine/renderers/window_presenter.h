// Frames in a window: GLFW surface, swapchain and the mesh renderer, with frames in flight. A
// resized, minimized or out-of-date window is a normal event: the swapchain is rebuilt and the
// frame skipped, never an error.
#pragma once

#include "gpu/glfw_window.h"
#include "gpu/swapchain.h"
#include "renderers/mesh_renderer.h"

#include <array>
#include <memory>

namespace ib::render {

struct WindowOptions {
  vk::WindowSpec window;                             // size and title
  bool vsync = true;                                 // FIFO presentation; off: mailbox or immediate when offered
  int samples = 4;                                   // MSAA samples, lowered to what the device supports
  std::array<float, 3> background{0.92f, 0.92f, 0.92f};  // RGB behind the artwork, light grey
  bool validation = false;                           // Khronos validation layer; messages via context()
  vk::DevicePreference device = vk::DevicePreference::kAny;
  int framesInFlight = 2;                            // 1..4
};

class WindowPresenter {
 public:
  // Opens the window and the Vulkan context on it. The mesh must outlive the presenter. Throws
  // WindowError (no display) or VulkanError (no device that presents to the window).
  WindowPresenter(const RenderMesh& mesh, const WindowOptions& options);
  ~WindowPresenter();
  WindowPresenter(const WindowPresenter&) = delete;
  WindowPresenter& operator=(const WindowPresenter&) = delete;

  // Draws and presents one frame; frame.view is widened to the window's aspect ratio. Returns
  // false when the frame was skipped: minimized, or the swapchain was out of date and rebuilt.
  bool present(const FrameDraw& frame);

  vk::GlfwWindow& window() { return *window_; }
  const vk::VulkanContext& context() const { return *context_; }
  VkExtent2D extent() const { return swapchain_->extent(); }
  int rebuilds() const { return rebuilds_; }  // swapchain builds after the first

 private:
  struct Frame {
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // freed with the pool
    vk::SemaphoreObject imageAvailable;
    vk::FenceObject fence;
  };
  void rebuild();

  std::unique_ptr<vk::GlfwWindow> window_;
  std::unique_ptr<vk::VulkanContext> context_;
  VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
  std::array<float, 4> clear_{};
  vk::CommandPoolObject pool_;
  std::unique_ptr<vk::Swapchain> swapchain_;
  vk::RenderPassObject pass_;
  std::unique_ptr<MeshRenderer> renderer_;
  std::vector<Frame> frames_;
  int current_ = 0;
  int rebuilds_ = 0;
};

}  // namespace ib::render
