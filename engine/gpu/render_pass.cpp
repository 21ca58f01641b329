#include "gpu/render_pass.h"

#include "gpu/vulkan_check.h"

#include <vector>

namespace ib::vk {

RenderPassObject createColorRenderPass(VkDevice device, VkFormat format, VkFormat stencil, VkSampleCountFlagBits samples,
                                       VkImageLayout finalLayout) {
  const bool multisampled = samples != VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkAttachmentDescription> attachments;
  VkAttachmentDescription colour{};
  colour.format = format;
  colour.samples = samples;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  colour.storeOp = multisampled ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  colour.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  colour.finalLayout = multisampled ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : finalLayout;
  attachments.push_back(colour);
  if (multisampled) {
    VkAttachmentDescription resolve = colour;
    resolve.samples = VK_SAMPLE_COUNT_1_BIT;
    resolve.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    resolve.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    resolve.finalLayout = finalLayout;
    attachments.push_back(resolve);
  }
  VkAttachmentDescription stencilAttachment{};
  stencilAttachment.format = stencil;
  stencilAttachment.samples = samples;
  stencilAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // the depth of a combined format: unused
  stencilAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  stencilAttachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  stencilAttachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  stencilAttachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  stencilAttachment.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  attachments.push_back(stencilAttachment);
  VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference resolveRef{1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference stencilRef{static_cast<uint32_t>(attachments.size() - 1), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colourRef;
  subpass.pResolveAttachments = multisampled ? &resolveRef : nullptr;
  subpass.pDepthStencilAttachment = &stencilRef;
  // In: earlier use of the images (a previous frame's copy or presentation) before this write.
  // Out: the stored image is then copied to the host (transfer) or presented.
  std::array<VkSubpassDependency, 2> dependencies{};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  // The stencil: the previous frame's tests and writes of the same image before this clear.
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                                 VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependencies[0].srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                 VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = static_cast<uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  VkRenderPass pass = VK_NULL_HANDLE;
  check(vkCreateRenderPass(device, &info, nullptr, &pass), "creating the render pass");
  return RenderPassObject(device, pass);
}

FramebufferObject createFramebuffer(VkDevice device, VkRenderPass pass, VkImageView msaaView, VkImageView targetView,
                                    VkImageView stencilView, VkExtent2D extent) {
  std::vector<VkImageView> views;
  if (msaaView != VK_NULL_HANDLE) views.push_back(msaaView);
  views.push_back(targetView);
  views.push_back(stencilView);
  VkFramebufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  info.renderPass = pass;
  info.attachmentCount = static_cast<uint32_t>(views.size());
  info.pAttachments = views.data();
  info.width = extent.width;
  info.height = extent.height;
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  check(vkCreateFramebuffer(device, &info, nullptr, &framebuffer), "creating a framebuffer");
  return FramebufferObject(device, framebuffer);
}

void beginRenderPass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer, VkExtent2D extent,
                     const std::array<float, 4>& clear) {
  // Colour, resolve (not cleared: loaded as don't-care) and stencil; where there is no resolve the
  // stencil's value sits at index 1 and reads the same.
  VkClearValue clearValues[3]{};
  for (int c = 0; c < 4; ++c) clearValues[0].color.float32[c] = clear[c];
  clearValues[1].depthStencil = {1.0f, 0};
  clearValues[2].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  begin.renderPass = pass;
  begin.framebuffer = framebuffer;
  begin.renderArea = {{0, 0}, extent};
  begin.clearValueCount = 3;
  begin.pClearValues = clearValues;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  VkViewport viewport{0, 0, static_cast<float>(extent.width), static_cast<float>(extent.height), 0, 1};
  VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

VkSampleCountFlagBits supportedSamples(VkPhysicalDevice physical, int wanted) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(physical, &properties);
  const VkSampleCountFlags allowed = properties.limits.framebufferColorSampleCounts;
  for (int s = 64; s > 1; s /= 2)
    if (s <= wanted && (allowed & static_cast<VkSampleCountFlags>(s))) return static_cast<VkSampleCountFlagBits>(s);
  return VK_SAMPLE_COUNT_1_BIT;
}

}  // namespace ib::vk
