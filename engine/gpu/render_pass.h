// The render pass every target draws with: one multisampled colour attachment resolved into a
// single-sampled image (the offscreen image or a swapchain image), cleared at the start.
#pragma once

#include "gpu/vulkan_object.h"

#include <array>

namespace ib::vk {

// samples == 1: one attachment, stored directly. samples > 1: attachment 0 multisampled
// (not stored), attachment 1 its resolve. The stored image ends in `finalLayout`
// (VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL for read-back, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR for a window).
RenderPassObject createColorRenderPass(VkDevice device, VkFormat format, VkSampleCountFlagBits samples,
                                       VkImageLayout finalLayout);

// A framebuffer over `msaaView` (may be VK_NULL_HANDLE when samples == 1) and `targetView`.
FramebufferObject createFramebuffer(VkDevice device, VkRenderPass pass, VkImageView msaaView, VkImageView targetView,
                                    VkExtent2D extent);

// Begins `pass` on `framebuffer`, clearing to `clear` (premultiplied RGBA), with viewport and
// scissor covering `extent`.
void beginRenderPass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer, VkExtent2D extent,
                     const std::array<float, 4>& clear);

// The largest sample count not above `wanted` that colour attachments support on this device.
VkSampleCountFlagBits supportedSamples(VkPhysicalDevice physical, int wanted);

}  // namespace ib::vk
