// The render pass every target draws with: one multisampled colour attachment resolved into a
// single-sampled image (the offscreen image or a swapchain image), and a stencil attachment of the
// same sample count, both cleared at the start (the stencil to 0). The stencil lets the keys' rims
// (render::KeyRim) draw only where their own frame has drawn nothing yet.
#pragma once

#include "gpu/vulkan_object.h"

#include <array>

namespace ib::vk {

// samples == 1: the colour attachment, stored directly, then the stencil. samples > 1: attachment 0
// multisampled (not stored), attachment 1 its resolve, attachment 2 the stencil (not stored). The
// stored image ends in `finalLayout` (VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL for read-back,
// VK_IMAGE_LAYOUT_PRESENT_SRC_KHR for a window). `stencil`: its format (stencilFormat).
RenderPassObject createColorRenderPass(VkDevice device, VkFormat format, VkFormat stencil, VkSampleCountFlagBits samples,
                                       VkImageLayout finalLayout);

// A framebuffer over `msaaView` (may be VK_NULL_HANDLE when samples == 1), `targetView` and
// `stencilView`, in createColorRenderPass's order.
FramebufferObject createFramebuffer(VkDevice device, VkRenderPass pass, VkImageView msaaView, VkImageView targetView,
                                    VkImageView stencilView, VkExtent2D extent);

// Begins `pass` on `framebuffer`, clearing to `clear` (premultiplied RGBA), with viewport and
// scissor covering `extent`.
void beginRenderPass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer, VkExtent2D extent,
                     const std::array<float, 4>& clear);

// The largest sample count not above `wanted` that colour attachments support on this device.
VkSampleCountFlagBits supportedSamples(VkPhysicalDevice physical, int wanted);

}  // namespace ib::vk
