// The editor's keys on screen: every key's drawing uploaded once (one array layer per key, as the
// mesh renderer's artwork), then drawn as a rectangle per view, each over a plain background and
// clipped to its part of the window. Records into a render pass the presenter has begun (the
// window's overlay callback), before the UI, so the editor's marks are drawn over the drawings.
#pragma once

#include "core/png_image.h"
#include "output/render_mesh.h"
#include "renderers/artwork_texture.h"
#include "renderers/renderer_pipelines.h"

#include <array>
#include <vector>

namespace ib::render {

// One key shown in one view.
struct SheetView {
  int key = 0;                   // which drawing
  ViewBox view;                  // the drawing pixels the whole window would show (y down)
  std::array<int, 4> scissor{};  // x, y, width, height: the window pixels the view may cover
  std::array<float, 4> background{0.80f, 0.80f, 0.81f, 1};  // straight RGBA filling the scissor first
  float opacity = 1;             // of the drawing
};

class DrawingSheet {
 public:
  // Uploads `drawings` (straight alpha) through `pool`. `pass` and `samples` are the target's.
  // Throws VulkanError (a drawing larger than the device's images) or std::invalid_argument (none).
  DrawingSheet(const vk::VulkanContext& context, VkCommandPool pool, const std::vector<RgbaImage>& drawings,
               VkRenderPass pass, VkSampleCountFlagBits samples);

  // Records every view into `cmd`, inside a begun render pass of `extent` pixels; leaves the
  // scissor set to the whole target. Views with an empty scissor or a key it does not hold are skipped.
  void record(VkCommandBuffer cmd, VkExtent2D extent, const std::vector<SheetView>& views, Sampling sampling) const;

  int keyCount() const { return static_cast<int>(sizes_.size()); }

 private:
  vk::SheetPipeline pipeline_;
  vk::ArtworkTexture artwork_;
  vk::DescriptorPoolObject descriptorPool_;
  std::array<VkDescriptorSet, 2> sets_{};      // [Sampling]; freed with the pool
  std::vector<std::array<int, 2>> sizes_;      // [key]: drawing width, height
};

}  // namespace ib::render
