#include "gpu/swapchain.h"

#include "gpu/render_pass.h"
#include "gpu/vulkan_check.h"

#include <algorithm>

namespace ib::vk {

Swapchain::Swapchain(const VulkanContext& context, bool vsync) : context_(&context) {
  VkPhysicalDevice physical = context.physicalDevice();
  VkSurfaceKHR surface = context.surface();
  uint32_t count = 0;
  check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr), "listing the window's surface formats");
  std::vector<VkSurfaceFormatKHR> formats(count);
  check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()), "listing the window's surface formats", true);
  if (formats.empty()) throw VulkanError("the window's surface offers no formats", VK_ERROR_FORMAT_NOT_SUPPORTED);
  const auto preferred = std::find_if(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
    return (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) &&
           f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  });
  const VkSurfaceFormatKHR chosen = preferred != formats.end() ? *preferred : formats.front();
  format_ = chosen.format;
  colorSpace_ = chosen.colorSpace;
  check(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr), "listing present modes");
  std::vector<VkPresentModeKHR> modes(count);
  check(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, modes.data()), "listing present modes", true);
  auto offered = [&](VkPresentModeKHR m) { return std::find(modes.begin(), modes.end(), m) != modes.end(); };
  if (!vsync) presentMode_ = offered(VK_PRESENT_MODE_MAILBOX_KHR) ? VK_PRESENT_MODE_MAILBOX_KHR
                             : offered(VK_PRESENT_MODE_IMMEDIATE_KHR) ? VK_PRESENT_MODE_IMMEDIATE_KHR
                                                                      : VK_PRESENT_MODE_FIFO_KHR;
}

void Swapchain::build(VkExtent2D size, VkRenderPass pass, VkSampleCountFlagBits samples) {
  VkDevice device = context_->device();
  check(vkDeviceWaitIdle(device), "waiting for the device before rebuilding the swapchain");
  VkSurfaceCapabilitiesKHR caps;
  check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_->physicalDevice(), context_->surface(), &caps),
        "reading the window surface's capabilities");
  extent_ = caps.currentExtent.width != UINT32_MAX
                ? caps.currentExtent
                : VkExtent2D{std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                             std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
  uint32_t imageCount = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);
  VkSwapchainCreateInfoKHR info{};
  info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
  info.surface = context_->surface();
  info.minImageCount = imageCount;
  info.imageFormat = format_;
  info.imageColorSpace = colorSpace_;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  // Transfer source too where the surface allows it, so a presented frame can be read back
  // (the player's screenshots, UI included).
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  readable_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_.get();
  VkSwapchainKHR handle = VK_NULL_HANDLE;
  check(vkCreateSwapchainKHR(device, &info, nullptr, &handle), "creating the swapchain");
  images_.clear();  // views and framebuffers of the old images go before the old swapchain
  swapchain_ = SwapchainObject(device, handle);
  check(vkGetSwapchainImagesKHR(device, handle, &imageCount, nullptr), "listing swapchain images");
  std::vector<VkImage> images(imageCount);
  check(vkGetSwapchainImagesKHR(device, handle, &imageCount, images.data()), "listing swapchain images", true);
  for (VkImage image : images) {
    SwapchainImage out;
    out.image = image;
    VkImageViewCreateInfo view{};
    view.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView viewHandle = VK_NULL_HANDLE;
    check(vkCreateImageView(device, &view, nullptr, &viewHandle), "creating a swapchain image view");
    out.view = ImageViewObject(device, viewHandle);
    if (samples != VK_SAMPLE_COUNT_1_BIT) {
      ImageSpec spec;
      spec.extent = extent_;
      spec.format = format_;
      spec.samples = samples;
      spec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
      out.msaa = createImage(*context_, spec, "the window's multisampled colour image");
    }
    ImageSpec stencil;
    stencil.extent = extent_;
    stencil.format = stencilFormat(context_->physicalDevice());
    stencil.samples = samples;
    stencil.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    out.stencil = createImage(*context_, stencil, "the window's stencil image");
    out.framebuffer = createFramebuffer(device, pass, out.msaa.view ? out.msaa.view.get() : VK_NULL_HANDLE, out.view.get(),
                                        out.stencil.view.get(), extent_);
    out.renderFinished = createSemaphore(device);
    images_.push_back(std::move(out));
  }
}

}  // namespace ib::vk
