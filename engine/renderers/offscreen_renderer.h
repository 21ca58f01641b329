// Headless rendering: frames drawn into an offscreen multisampled target, resolved, copied back
// to the host and returned as straight-alpha RGBA (what PNG files hold). No window system needed.
// Frames are pipelined: submit() returns at once while up to `framesInFlight` frames render; take()
// returns the oldest one's pixels, waiting for it.
#pragma once

#include "core/png_image.h"
#include "renderers/mesh_renderer.h"

#include <array>
#include <deque>
#include <memory>
#include <vector>

namespace ib::render {

struct OffscreenOptions {
  int width = 1280, height = 720;               // pixels, 1..maxImageDimension2D
  int samples = 4;                              // MSAA samples; lowered to what the device supports
  std::array<float, 4> background{0, 0, 0, 0};  // straight RGBA in [0, 1]; default transparent
  int framesInFlight = 2;                       // frames submitted before take() must wait, >= 1
};

class OffscreenRenderer {
 public:
  // The context and mesh must outlive the renderer. Throws InputError for a bad size or option,
  // VulkanError when the device cannot do it.
  OffscreenRenderer(const vk::VulkanContext& context, const RenderMesh& mesh, const OffscreenOptions& options);
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  // Queues a frame. When every slot is busy, first waits for the oldest and keeps its pixels for take().
  void submit(const FrameDraw& frame);
  // The oldest submitted frame not yet taken, waiting for it. Throws std::logic_error when none is pending.
  RgbaImage take();
  int pending() const { return static_cast<int>(order_.size() + finished_.size()); }
  // submit() then take(): one frame, synchronously.
  RgbaImage render(const FrameDraw& frame);

  VkSampleCountFlagBits samples() const { return samples_; }
  VkExtent2D extent() const { return extent_; }

 private:
  struct Slot;
  RgbaImage readBack(Slot& slot);

  const vk::VulkanContext* context_;
  VkExtent2D extent_{};
  VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
  std::array<float, 4> clear_{};  // premultiplied background
  vk::CommandPoolObject pool_;
  vk::RenderPassObject pass_;
  std::unique_ptr<MeshRenderer> renderer_;
  std::vector<std::unique_ptr<Slot>> slots_;
  std::deque<int> order_;              // submitted slots, oldest first
  std::deque<RgbaImage> finished_;     // pixels read back early to free a slot, oldest first
  int nextSlot_ = 0;
};

// Straight alpha from premultiplied RGBA8, in place: c * 255 / a, rounded; a = 0 gives black.
void unpremultiply(RgbaImage& image);

}  // namespace ib::render
