#include "renderers/window_presenter.h"

#include "core/error.h"
#include "gpu/render_pass.h"
#include "gpu/vulkan_check.h"

namespace ib::render {

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
  clear_ = {options.background[0], options.background[1], options.background[2], 1};
  samples_ = vk::supportedSamples(context_->physicalDevice(), options.samples);
  pool_ = vk::createCommandPool(*context_);
  swapchain_ = std::make_unique<vk::Swapchain>(*context_, options.vsync);
  pass_ = vk::createColorRenderPass(context_->device(), swapchain_->format(), samples_, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
  renderer_ = std::make_unique<MeshRenderer>(*context_, pool_.get(), mesh, pass_.get(), samples_, options.framesInFlight);
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

void WindowPresenter::rebuild() {
  swapchain_->build(window_->framebufferSize(), pass_.get(), samples_);
  ++rebuilds_;
}

bool WindowPresenter::present(const FrameDraw& frame) {
  const VkExtent2D size = window_->framebufferSize();
  if (size.width == 0 || size.height == 0) return false;  // minimized: nothing to draw into
  if (window_->takeResized() || size.width != swapchain_->extent().width || size.height != swapchain_->extent().height)
    rebuild();
  VkDevice device = context_->device();
  Frame& f = frames_[current_];
  VkFence fence = f.fence.get();
  vk::check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "waiting for a frame in flight");
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
  vk::beginRenderPass(f.cmd, pass_.get(), image.framebuffer.get(), swapchain_->extent(), clear_);
  FrameDraw fitted = frame;
  fitted.view = fitView(frame.view, static_cast<int>(swapchain_->extent().width), static_cast<int>(swapchain_->extent().height), 0);
  renderer_->record(f.cmd, current_, swapchain_->extent(), fitted);
  vkCmdEndRenderPass(f.cmd);
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
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR || acquired == VK_SUBOPTIMAL_KHR) {
    rebuild();
    return presented != VK_ERROR_OUT_OF_DATE_KHR;
  }
  vk::check(presented, "presenting a frame (vkQueuePresentKHR)");
  return true;
}

}  // namespace ib::render
