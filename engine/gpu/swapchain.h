// The window's swapchain and what draws into each of its images: image views, a multisampled
// colour image per image, framebuffers and a render-finished semaphore per image. Rebuilt whole
// when the window changes size or the surface reports it out of date.
#pragma once

#include "gpu/gpu_resources.h"
#include "gpu/vulkan_object.h"

#include <vector>

namespace ib::vk {

using SwapchainObject = DeviceObject<VkSwapchainKHR, vkDestroySwapchainKHR>;

struct SwapchainImage {
  VkImage image = VK_NULL_HANDLE;  // owned by the swapchain
  ImageViewObject view;
  GpuImage msaa;                   // absent when samples == 1
  GpuImage stencil;                // the render pass's stencil, `samples` samples
  FramebufferObject framebuffer;
  SemaphoreObject renderFinished;  // signalled by the frame drawn into this image, waited on by present
  VkFence inFlight = VK_NULL_HANDLE;  // the fence of the frame last drawn into it (not owned)
};

class Swapchain {
 public:
  // Chooses the surface format once (BGRA or RGBA 8-bit UNORM when offered, so colours match the
  // offscreen path); `vsync` picks FIFO, otherwise MAILBOX or IMMEDIATE when offered.
  Swapchain(const VulkanContext& context, bool vsync);
  VkFormat format() const { return format_; }

  // (Re)builds for a framebuffer of `size` pixels (clamped to what the surface allows) with the
  // render pass `pass`. Waits for the device to go idle first. Throws VulkanError.
  void build(VkExtent2D size, VkRenderPass pass, VkSampleCountFlagBits samples);

  VkSwapchainKHR get() const { return swapchain_.get(); }
  VkExtent2D extent() const { return extent_; }
  // The images can be copied from (VK_IMAGE_USAGE_TRANSFER_SRC_BIT, when the surface offers it).
  bool readable() const { return readable_; }
  std::vector<SwapchainImage>& images() { return images_; }

 private:
  const VulkanContext* context_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkExtent2D extent_{};
  bool readable_ = false;
  SwapchainObject swapchain_;
  std::vector<SwapchainImage> images_;
};

}  // namespace ib::vk
