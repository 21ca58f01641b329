#include "renderers/drawing_sheet.h"

#include "gpu/vulkan_check.h"

#include <algorithm>
#include <stdexcept>

namespace ib::render {

DrawingSheet::DrawingSheet(const vk::VulkanContext& context, VkCommandPool pool, const std::vector<RgbaImage>& drawings,
                           VkRenderPass pass, VkSampleCountFlagBits samples) {
  if (drawings.empty()) throw std::invalid_argument("drawing sheet: no drawings");
  for (const RgbaImage& d : drawings) sizes_.push_back({d.width, d.height});
  VkDevice device = context.device();
  pipeline_ = vk::createSheetPipeline(device, pass, samples);
  artwork_ = vk::uploadArtwork(context, pool, drawings);
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2};
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.maxSets = 2;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
  vk::check(vkCreateDescriptorPool(device, &poolInfo, nullptr, &descriptorPool), "creating the drawing sheet's descriptor pool");
  descriptorPool_ = vk::DescriptorPoolObject(device, descriptorPool);
  const VkDescriptorSetLayout layouts[2] = {pipeline_.setLayout.get(), pipeline_.setLayout.get()};
  VkDescriptorSetAllocateInfo allocate{};
  allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  allocate.descriptorPool = descriptorPool;
  allocate.descriptorSetCount = 2;
  allocate.pSetLayouts = layouts;
  vk::check(vkAllocateDescriptorSets(device, &allocate, sets_.data()), "allocating the drawing sheet's descriptor sets");
  const VkSampler samplers[2] = {artwork_.linear.get(), artwork_.nearest.get()};  // [Sampling]
  VkDescriptorImageInfo images[2];
  VkWriteDescriptorSet writes[2] = {};
  for (int s = 0; s < 2; ++s) {
    images[s] = {samplers[s], artwork_.image.view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    writes[s].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[s].dstSet = sets_[s];
    writes[s].dstBinding = 0;
    writes[s].descriptorCount = 1;
    writes[s].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[s].pImageInfo = &images[s];
  }
  vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);
}

void DrawingSheet::record(VkCommandBuffer cmd, VkExtent2D extent, const std::vector<SheetView>& views, Sampling sampling) const {
  const float w = static_cast<float>(std::max(1u, extent.width)), h = static_cast<float>(std::max(1u, extent.height));
  const VkViewport viewport{0, 0, w, h, 0, 1};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.pipeline.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.layout.get(), 0, 1,
                          &sets_[sampling == Sampling::kNearest ? 1 : 0], 0, nullptr);
  const auto push = [&](const vk::SheetPush& p) {
    vkCmdPushConstants(cmd, pipeline_.layout.get(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof p, &p);
    vkCmdDraw(cmd, 6, 1, 0, 0);
  };
  for (const SheetView& v : views) {
    if (v.key < 0 || v.key >= keyCount()) continue;  // a key added since the sheet was made: drawn from the next frame
    // The scissor within the target (Vulkan wants it non-negative and inside).
    const int x0 = std::clamp(v.scissor[0], 0, static_cast<int>(extent.width));
    const int y0 = std::clamp(v.scissor[1], 0, static_cast<int>(extent.height));
    const int x1 = std::clamp(v.scissor[0] + v.scissor[2], x0, static_cast<int>(extent.width));
    const int y1 = std::clamp(v.scissor[1] + v.scissor[3], y0, static_cast<int>(extent.height));
    if (x1 <= x0 || y1 <= y0) continue;
    const VkRect2D scissor{{x0, y0}, {static_cast<uint32_t>(x1 - x0), static_cast<uint32_t>(y1 - y0)}};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vk::SheetPush fill{};
    fill.clipRect[0] = fill.clipRect[1] = -1;
    fill.clipRect[2] = fill.clipRect[3] = 1;
    const float a = v.background[3];
    for (int c = 0; c < 3; ++c) fill.colour[c] = v.background[c] * a;
    fill.colour[3] = a;
    fill.layer = -1;
    push(fill);
    // The drawing's rectangle [0, width] x [0, height] under the view, in clip space (y down in both).
    const auto clipX = [&](double x) { return static_cast<float>(2 * (x - v.view.x0) / (v.view.x1 - v.view.x0) - 1); };
    const auto clipY = [&](double y) { return static_cast<float>(2 * (y - v.view.y0) / (v.view.y1 - v.view.y0) - 1); };
    const auto& size = sizes_[static_cast<size_t>(v.key)];
    vk::SheetPush drawing{};
    drawing.clipRect[0] = clipX(0);
    drawing.clipRect[1] = clipY(0);
    drawing.clipRect[2] = clipX(size[0]);
    drawing.clipRect[3] = clipY(size[1]);
    drawing.uvRect[2] = static_cast<float>(size[0]) / artwork_.layerSize.width;
    drawing.uvRect[3] = static_cast<float>(size[1]) / artwork_.layerSize.height;
    for (float& c : drawing.colour) c = v.opacity;
    drawing.layer = v.key;
    push(drawing);
  }
  const VkRect2D whole{{0, 0}, {extent.width, extent.height}};
  vkCmdSetScissor(cmd, 0, 1, &whole);
}

}  // namespace ib::render
