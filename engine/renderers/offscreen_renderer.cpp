#include "renderers/offscreen_renderer.h"

#include "core/error.h"
#include "gpu/render_pass.h"
#include "gpu/vulkan_check.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace ib::render {

namespace {
constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_UNORM;
}

struct OffscreenRenderer::Slot {
  vk::GpuImage msaa;      // absent when samples == 1
  vk::GpuImage resolved;  // single-sampled, copied to `readback`
  vk::GpuImage stencil;   // the render pass's stencil, as many samples as `msaa`
  vk::FramebufferObject framebuffer;
  vk::GpuBuffer readback;  // host-visible, width * height * 4 bytes
  VkCommandBuffer cmd = VK_NULL_HANDLE;  // freed with the pool
  vk::FenceObject fence;
};

void unpremultiply(RgbaImage& image) {
  for (size_t p = 0; p + 3 < image.pixels.size(); p += 4) {
    const unsigned a = image.pixels[p + 3];
    if (a == 255) continue;  // opaque: premultiplied and straight agree
    for (int c = 0; c < 3; ++c)
      image.pixels[p + c] = a == 0 ? 0 : static_cast<uint8_t>(std::min(255u, (image.pixels[p + c] * 255u + a / 2) / a));
  }
}

OffscreenRenderer::OffscreenRenderer(const vk::VulkanContext& context, const RenderMesh& mesh, const OffscreenOptions& options)
    : context_(&context) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
  const int largest = static_cast<int>(properties.limits.maxFramebufferWidth < properties.limits.maxFramebufferHeight
                                           ? properties.limits.maxFramebufferWidth
                                           : properties.limits.maxFramebufferHeight);
  if (options.width < 1 || options.height < 1 || options.width > largest || options.height > largest)
    throw InputError("render: size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                     " is outside 1.." + std::to_string(largest) + " pixels");
  if (options.framesInFlight < 1 || options.framesInFlight > 8) throw InputError("render: frames in flight must be in 1..8");
  if (options.samples < 1) throw InputError("render: samples must be at least 1");
  for (float c : options.background)
    if (!(c >= 0 && c <= 1)) throw InputError("render: background components must be in [0, 1]");
  extent_ = {static_cast<uint32_t>(options.width), static_cast<uint32_t>(options.height)};
  samples_ = vk::supportedSamples(context.physicalDevice(), options.samples);
  const float a = options.background[3];
  clear_ = {options.background[0] * a, options.background[1] * a, options.background[2] * a, a};
  VkDevice device = context.device();
  pool_ = vk::createCommandPool(context);
  const VkFormat stencil = vk::stencilFormat(context.physicalDevice());
  pass_ = vk::createColorRenderPass(device, kFormat, stencil, samples_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  renderer_ = std::make_unique<MeshRenderer>(
      context, pool_.get(), mesh, std::make_shared<const vk::RendererPipelines>(vk::createRendererPipelines(device, pass_.get(), samples_)),
      options.framesInFlight);
  for (int s = 0; s < options.framesInFlight; ++s) {
    auto slot = std::make_unique<Slot>();
    vk::ImageSpec spec;
    spec.extent = extent_;
    spec.format = kFormat;
    if (samples_ != VK_SAMPLE_COUNT_1_BIT) {
      spec.samples = samples_;
      spec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
      slot->msaa = vk::createImage(context, spec, "the multisampled colour target");
    }
    vk::ImageSpec stencilSpec = spec;
    stencilSpec.format = stencil;
    stencilSpec.samples = samples_;
    stencilSpec.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    slot->stencil = vk::createImage(context, stencilSpec, "the offscreen stencil");
    spec.samples = VK_SAMPLE_COUNT_1_BIT;
    spec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    slot->resolved = vk::createImage(context, spec, "the offscreen colour target");
    slot->framebuffer = vk::createFramebuffer(device, pass_.get(), slot->msaa.view ? slot->msaa.view.get() : VK_NULL_HANDLE,
                                              slot->resolved.view.get(), slot->stencil.view.get(), extent_);
    slot->readback = vk::createBuffer(context, static_cast<VkDeviceSize>(extent_.width) * extent_.height * 4,
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "the read-back buffer");
    VkCommandBufferAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocate.commandPool = pool_.get();
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    vk::check(vkAllocateCommandBuffers(device, &allocate, &slot->cmd), "allocating a frame's command buffer");
    slot->fence = vk::createFence(device, true);
    slots_.push_back(std::move(slot));
  }
}

OffscreenRenderer::~OffscreenRenderer() {
  // Frames still in flight use the slots' buffers and images: let them finish first.
  if (context_ && context_->device()) vkDeviceWaitIdle(context_->device());
}

void OffscreenRenderer::submit(const FrameDraw& frame) {
  if (static_cast<int>(order_.size()) == static_cast<int>(slots_.size())) {
    const int oldest = order_.front();
    order_.pop_front();
    finished_.push_back(readBack(*slots_[oldest]));
  }
  const int s = nextSlot_;
  Slot& slot = *slots_[s];
  VkFence fence = slot.fence.get();
  vk::check(vkWaitForFences(context_->device(), 1, &fence, VK_TRUE, UINT64_MAX), "waiting for a frame slot");
  vk::check(vkResetCommandBuffer(slot.cmd, 0), "resetting a frame's command buffer");
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk::check(vkBeginCommandBuffer(slot.cmd, &begin), "beginning a frame's command buffer");
  vk::beginRenderPass(slot.cmd, pass_.get(), slot.framebuffer.get(), extent_, clear_);
  renderer_->record(slot.cmd, s, extent_, frame);  // may throw on a bad frame: the slot stays free
  vkCmdEndRenderPass(slot.cmd);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyImageToBuffer(slot.cmd, slot.resolved.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, slot.readback.buffer.get(), 1,
                         &region);
  VkBufferMemoryBarrier toHost{};
  toHost.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  toHost.buffer = slot.readback.buffer.get();
  toHost.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(slot.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 0, nullptr);
  vk::check(vkEndCommandBuffer(slot.cmd), "recording a frame");
  vk::check(vkResetFences(context_->device(), 1, &fence), "resetting a frame's fence");
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &slot.cmd;
  vk::check(vkQueueSubmit(context_->queue(), 1, &submit, fence), "submitting a frame (vkQueueSubmit)");
  order_.push_back(s);
  nextSlot_ = (s + 1) % static_cast<int>(slots_.size());
}

RgbaImage OffscreenRenderer::readBack(Slot& slot) {
  VkFence fence = slot.fence.get();
  vk::check(vkWaitForFences(context_->device(), 1, &fence, VK_TRUE, UINT64_MAX), "waiting for a frame to render");
  RgbaImage image;
  image.width = static_cast<int>(extent_.width);
  image.height = static_cast<int>(extent_.height);
  image.hasAlpha = true;
  image.pixels.resize(static_cast<size_t>(image.width) * image.height * 4);
  std::memcpy(image.pixels.data(), slot.readback.mapped, image.pixels.size());
  unpremultiply(image);
  return image;
}

RgbaImage OffscreenRenderer::take() {
  if (!finished_.empty()) {
    RgbaImage image = std::move(finished_.front());
    finished_.pop_front();
    return image;
  }
  if (order_.empty()) throw std::logic_error("OffscreenRenderer::take: no frame pending");
  const int oldest = order_.front();
  order_.pop_front();
  return readBack(*slots_[oldest]);
}

RgbaImage OffscreenRenderer::render(const FrameDraw& frame) {
  submit(frame);
  return take();
}

}  // namespace ib::render
