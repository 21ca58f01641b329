#include "renderers/window_presenter.h"

#include "core/error.h"
#include "gpu/render_pass.h"
#include "gpu/vulkan_check.h"

#include <algorithm>
#include <cstring>

namespace ib::render {

namespace {

vk::DescriptorPoolObject createOverlayPool(VkDevice device) {
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
  VkDescriptorPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  info.maxSets = 16;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  vk::check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "creating the UI's descriptor pool");
  return vk::DescriptorPoolObject(device, pool);
}

}  // namespace

WindowPresenter::WindowPresenter(const RenderMesh& mesh, const WindowOptions& options) {
  if (options.framesInFlight < 1 || options.framesInFlight > 4) throw InputError("window: frames in flight must be in 1..4");
  window_ = std::make_unique<vk::GlfwWindow>(options.window);
  vk::ContextOptions contextOptions;
  contextOptions.validation = options.validation;
  contextOptions.device = options.device;
  contextOptions.instanceExtensions = vk::GlfwWindow::requiredExtensions();
  contextOptions.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  contextOptions.createSurface = [this](VkInstance instance) { return window_->createSurface(instance); };
  context_ = std::make_unique<vk::VulkanContext>(contextOptions);
  backdrop_.colour = options.background;
  framesInFlight_ = options.framesInFlight;
  samples_ = vk::supportedSamples(context_->physicalDevice(), options.samples);
  pool_ = vk::createCommandPool(*context_);
  swapchain_ = std::make_unique<vk::Swapchain>(*context_, options.vsync);
  pass_ = vk::createColorRenderPass(context_->device(), swapchain_->format(), vk::stencilFormat(context_->physicalDevice()), samples_,
                                    VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
  overlayPool_ = createOverlayPool(context_->device());
  pipelines_ = std::make_shared<const vk::RendererPipelines>(vk::createRendererPipelines(context_->device(), pass_.get(), samples_));
  renderer_ = std::make_unique<MeshRenderer>(*context_, pool_.get(), mesh, pipelines_, options.framesInFlight);
  for (int f = 0; f < options.framesInFlight; ++f) {
    Frame frame;
    VkCommandBufferAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocate.commandPool = pool_.get();
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    vk::check(vkAllocateCommandBuffers(context_->device(), &allocate, &frame.cmd), "allocating a frame's command buffer");
    frame.imageAvailable = vk::createSemaphore(context_->device());
    frame.fence = vk::createFence(context_->device(), true);
    frames_.push_back(std::move(frame));
  }
  swapchain_->build(window_->framebufferSize(), pass_.get(), samples_);
}

WindowPresenter::~WindowPresenter() {
  if (context_) vkDeviceWaitIdle(context_->device());
}

void WindowPresenter::prepareMesh(const RenderMesh& mesh) {
  prepared_ = std::make_unique<MeshRenderer>(*context_, pool_.get(), mesh, pipelines_, framesInFlight_);
}

bool WindowPresenter::usePreparedMesh() {
  if (!prepared_) return false;
  retired_.emplace_back(std::move(renderer_), submitted_);
  renderer_ = std::move(prepared_);
  return true;
}

void WindowPresenter::setBackdrop(const Backdrop& backdrop) {
  if (backdrop.square < 1) throw std::invalid_argument("window: a checkerboard square must be at least one pixel");
  backdrop_ = backdrop;
}

OverlayTarget WindowPresenter::overlayTarget() const {
  OverlayTarget target;
  target.instance = context_->instance();
  target.physicalDevice = context_->physicalDevice();
  target.device = context_->device();
  target.queueFamily = context_->queueFamily();
  target.queue = context_->queue();
  target.renderPass = pass_.get();
  target.minImageCount = 2;
  target.imageCount = static_cast<uint32_t>(std::max<size_t>(swapchain_->images().size(), frames_.size() + 1));
  target.samples = samples_;
  target.descriptorPool = overlayPool_.get();
  return target;
}

void WindowPresenter::submitOnce(const std::function<void(VkCommandBuffer)>& record) {
  vk::submitAndWait(*context_, pool_.get(), record);
}

void WindowPresenter::waitIdle() { vk::check(vkDeviceWaitIdle(context_->device()), "waiting for the frames in flight"); }

void WindowPresenter::recordBackdrop(VkCommandBuffer cmd) const {
  if (!backdrop_.checkerboard) return;  // the render pass cleared to the colour
  const VkExtent2D extent = swapchain_->extent();
  const uint32_t square = static_cast<uint32_t>(backdrop_.square);
  std::vector<VkClearRect> rects;
  for (uint32_t y = 0; y * square < extent.height; ++y)
    for (uint32_t x = (y + 1) % 2; x * square < extent.width; x += 2) {
      const VkRect2D rect{{static_cast<int32_t>(x * square), static_cast<int32_t>(y * square)},
                          {std::min(square, extent.width - x * square), std::min(square, extent.height - y * square)}};
      rects.push_back({rect, 0, 1});
    }
  if (rects.empty()) return;
  VkClearAttachment clear{};
  clear.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
  clear.colorAttachment = 0;
  for (int c = 0; c < 3; ++c) clear.clearValue.color.float32[c] = backdrop_.second[c];
  clear.clearValue.color.float32[3] = 1;
  vkCmdClearAttachments(cmd, 1, &clear, static_cast<uint32_t>(rects.size()), rects.data());
}

void WindowPresenter::recordCapture(VkCommandBuffer cmd, VkImage image, VkBuffer buffer) const {
  vk::transitionImage(cmd, image, 1, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {swapchain_->extent().width, swapchain_->extent().height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
  vk::transitionImage(cmd, image, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
}

RgbaImage WindowPresenter::readCapture(const vk::GpuBuffer& buffer) const {
  RgbaImage image;
  image.width = static_cast<int>(swapchain_->extent().width);
  image.height = static_cast<int>(swapchain_->extent().height);
  image.pixels.resize(static_cast<size_t>(image.width) * image.height * 4);
  std::memcpy(image.pixels.data(), buffer.mapped, image.pixels.size());
  const bool bgra = swapchain_->format() == VK_FORMAT_B8G8R8A8_UNORM;
  for (size_t p = 0; p < image.pixels.size(); p += 4) {
    if (bgra) std::swap(image.pixels[p], image.pixels[p + 2]);
    image.pixels[p + 3] = 255;  // the window is opaque
  }
  return image;
}

void WindowPresenter::rebuild() {
  swapchain_->build(window_->framebufferSize(), pass_.get(), samples_);
  ++rebuilds_;
}

bool WindowPresenter::present(const FrameDraw& frame, const Overlay& overlay, RgbaImage* capture) {
  if (capture && !canCapture()) throw std::invalid_argument("window: this surface's images cannot be read back");
  const VkExtent2D size = window_->framebufferSize();
  if (size.width == 0 || size.height == 0) return false;  // minimized: nothing to draw into
  if (window_->takeResized() || size.width != swapchain_->extent().width || size.height != swapchain_->extent().height)
    rebuild();
  VkDevice device = context_->device();
  Frame& f = frames_[current_];
  VkFence fence = f.fence.get();
  vk::check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "waiting for a frame in flight");
  // A fence of a queue submission signals after every earlier submission to the queue too.
  completed_ = std::max(completed_, f.submission);
  retired_.erase(std::remove_if(retired_.begin(), retired_.end(), [&](const auto& r) { return r.second <= completed_; }),
                 retired_.end());
  uint32_t index = 0;
  const VkResult acquired =
      vkAcquireNextImageKHR(device, swapchain_->get(), UINT64_MAX, f.imageAvailable.get(), VK_NULL_HANDLE, &index);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    rebuild();
    return false;
  }
  vk::check(acquired, "acquiring a swapchain image", true);  // VK_SUBOPTIMAL_KHR: draw, rebuild after
  vk::SwapchainImage& image = swapchain_->images()[index];
  if (image.inFlight != VK_NULL_HANDLE)
    vk::check(vkWaitForFences(device, 1, &image.inFlight, VK_TRUE, UINT64_MAX), "waiting for a swapchain image's last frame");
  image.inFlight = fence;

  vk::check(vkResetCommandBuffer(f.cmd, 0), "resetting a frame's command buffer");
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk::check(vkBeginCommandBuffer(f.cmd, &begin), "beginning a frame's command buffer");
  const std::array<float, 4> clear{backdrop_.colour[0], backdrop_.colour[1], backdrop_.colour[2], 1};
  vk::beginRenderPass(f.cmd, pass_.get(), image.framebuffer.get(), swapchain_->extent(), clear);
  recordBackdrop(f.cmd);
  if (frame.positions) {
    FrameDraw fitted = frame;
    fitted.view = fitView(frame.view, static_cast<int>(swapchain_->extent().width), static_cast<int>(swapchain_->extent().height), 0);
    renderer_->record(f.cmd, current_, swapchain_->extent(), fitted);
  }
  if (overlay) overlay(f.cmd);
  vkCmdEndRenderPass(f.cmd);
  vk::GpuBuffer readback;
  if (capture) {
    const VkDeviceSize bytes = VkDeviceSize(swapchain_->extent().width) * swapchain_->extent().height * 4;
    readback = vk::createBuffer(*context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "the screenshot read-back buffer");
    recordCapture(f.cmd, image.image, readback.buffer.get());
  }
  vk::check(vkEndCommandBuffer(f.cmd), "recording a frame");

  vk::check(vkResetFences(device, 1, &fence), "resetting a frame's fence");
  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  const VkSemaphore available = f.imageAvailable.get(), finished = image.renderFinished.get();
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &available;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &f.cmd;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &finished;
  vk::check(vkQueueSubmit(context_->queue(), 1, &submit, fence), "submitting a frame (vkQueueSubmit)");
  f.submission = ++submitted_;

  const VkSwapchainKHR swapchain = swapchain_->get();
  VkPresentInfoKHR present{};
  present.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &finished;
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain;
  present.pImageIndices = &index;
  const VkResult presented = vkQueuePresentKHR(context_->queue(), &present);
  current_ = (current_ + 1) % static_cast<int>(frames_.size());
  if (capture) {  // the copy ran before the present, in the frame's submission
    vk::check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "waiting for a captured frame");
    *capture = readCapture(readback);
  }
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR || acquired == VK_SUBOPTIMAL_KHR) {
    rebuild();
    return presented != VK_ERROR_OUT_OF_DATE_KHR;
  }
  vk::check(presented, "presenting a frame (vkQueuePresentKHR)");
  return true;
}

}  // namespace ib::render
