// Frames in a window: GLFW surface, swapchain and the mesh renderer, with frames in flight. A
// resized, minimized or out-of-date window is a normal event: the swapchain is rebuilt and the
// frame skipped, never an error. A UI (the player's Dear ImGui) draws into the same render pass
// after the mesh through an overlay callback, and a presented frame can be read back, UI included.
#pragma once

#include "gpu/glfw_window.h"
#include "gpu/swapchain.h"
#include "renderers/mesh_renderer.h"

#include <array>
#include <functional>
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

// What is behind the artwork: one colour, or a checkerboard of two in window pixels (as paint
// programs show transparency).
struct Backdrop {
  std::array<float, 3> colour{0.92f, 0.92f, 0.92f};  // RGB; the checkerboard's first colour
  bool checkerboard = false;
  std::array<float, 3> second{0.78f, 0.78f, 0.78f};  // the checkerboard's other squares
  int square = 16;                                   // window pixels per checkerboard square, >= 1
};

// What a UI renderer (Dear ImGui's Vulkan backend) needs to draw inside the presenter's render
// pass. The handles stay valid for the presenter's lifetime (the render pass survives swapchain
// rebuilds); the descriptor pool is the presenter's and is the UI's alone.
struct OverlayTarget {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  uint32_t minImageCount = 2;  // >= 2
  uint32_t imageCount = 3;     // > frames in flight, so per-frame UI buffers are not reused too soon
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;  // combined image samplers, sets freeable
};

// Records more drawing into the frame's command buffer, inside the render pass, after the mesh.
using Overlay = std::function<void(VkCommandBuffer)>;

class WindowPresenter {
 public:
  // Opens the window and the Vulkan context on it, and uploads `mesh` (the renderer copies what
  // it draws). Throws WindowError (no display) or VulkanError (no device that presents to the
  // window).
  WindowPresenter(const RenderMesh& mesh, const WindowOptions& options);
  ~WindowPresenter();
  WindowPresenter(const WindowPresenter&) = delete;
  WindowPresenter& operator=(const WindowPresenter&) = delete;

  // Draws and presents one frame: the backdrop, the mesh (unless frame.positions is null: nothing
  // solved yet), then `overlay`. frame.view is widened to the window's aspect ratio. With
  // `capture`, waits for the frame and copies the presented image into it (opaque RGBA, rows top to
  // bottom; needs canCapture()). Returns false when the frame was skipped: minimized, or the
  // swapchain was out of date and rebuilt (then `capture` is untouched).
  bool present(const FrameDraw& frame, const Overlay& overlay = {}, RgbaImage* capture = nullptr);

  // Uploads `mesh` (a scene reloaded with another topology) for usePreparedMesh, while the current
  // one is still drawn: its artwork's copy runs on the queue meanwhile. Replaces a mesh prepared
  // earlier and not used.
  void prepareMesh(const RenderMesh& mesh);
  // Draws the prepared mesh from the next frame on; false (nothing changes) when none is prepared.
  // The frames in flight finish with the old one, which is released once they have (no wait here).
  bool usePreparedMesh();
  void setBackdrop(const Backdrop& backdrop);
  const Backdrop& backdrop() const { return backdrop_; }

  OverlayTarget overlayTarget() const;
  // Records commands with `record`, submits them and waits (uploads such as a UI's font atlas).
  void submitOnce(const std::function<void(VkCommandBuffer)>& record);
  // Waits for every frame in flight (before the UI's objects are destroyed).
  void waitIdle();
  bool canCapture() const { return swapchain_->readable(); }

  vk::GlfwWindow& window() { return *window_; }
  const vk::VulkanContext& context() const { return *context_; }
  VkExtent2D extent() const { return swapchain_->extent(); }
  int rebuilds() const { return rebuilds_; }  // swapchain builds after the first

 private:
  struct Frame {
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // freed with the pool
    vk::SemaphoreObject imageAvailable;
    vk::FenceObject fence;
    uint64_t submission = 0;  // the number of its last submission (submitted_ then)
  };
  void rebuild();
  void recordBackdrop(VkCommandBuffer cmd) const;
  // After the render pass: copies `image` (in PRESENT_SRC layout) into `buffer` and back.
  void recordCapture(VkCommandBuffer cmd, VkImage image, VkBuffer buffer) const;
  RgbaImage readCapture(const vk::GpuBuffer& buffer) const;

  std::unique_ptr<vk::GlfwWindow> window_;
  std::unique_ptr<vk::VulkanContext> context_;
  VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
  Backdrop backdrop_;
  int framesInFlight_ = 2;
  vk::CommandPoolObject pool_;
  std::unique_ptr<vk::Swapchain> swapchain_;
  vk::RenderPassObject pass_;
  vk::DescriptorPoolObject overlayPool_;
  std::shared_ptr<const vk::RendererPipelines> pipelines_;  // for pass_ and samples_, every mesh's
  std::unique_ptr<MeshRenderer> renderer_;
  std::unique_ptr<MeshRenderer> prepared_;  // prepareMesh's, until usePreparedMesh
  // Renderers replaced by usePreparedMesh, with submitted_ then: released once that submission is done.
  std::vector<std::pair<std::unique_ptr<MeshRenderer>, uint64_t>> retired_;
  uint64_t submitted_ = 0;  // frames submitted so far
  uint64_t completed_ = 0;  // every submission up to this one has finished (a frame's fence waited)
  std::vector<Frame> frames_;
  int current_ = 0;
  int rebuilds_ = 0;
};

}  // namespace ib::render
