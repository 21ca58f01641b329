#include "gpu/gpu_resources.h"

#include "gpu/vulkan_check.h"

#include <cstring>
#include <utility>
#include <string>

namespace ib::vk {

namespace {

// Index of a memory type allowed by `typeBits` with all `required` properties, or throws.
uint32_t memoryType(VkPhysicalDevice physical, uint32_t typeBits, VkMemoryPropertyFlags required, const char* what) {
  VkPhysicalDeviceMemoryProperties properties;
  vkGetPhysicalDeviceMemoryProperties(physical, &properties);
  for (uint32_t i = 0; i < properties.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (properties.memoryTypes[i].propertyFlags & required) == required) return i;
  throw VulkanError(std::string("no suitable memory type for ") + what, VK_ERROR_FEATURE_NOT_PRESENT);
}

MemoryObject allocate(const VulkanContext& context, const VkMemoryRequirements& needs, VkMemoryPropertyFlags properties,
                      const char* what) {
  VkMemoryAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  info.allocationSize = needs.size;
  info.memoryTypeIndex = memoryType(context.physicalDevice(), needs.memoryTypeBits, properties, what);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(context.device(), &info, nullptr, &memory), (std::string("allocating memory for ") + what).c_str());
  return MemoryObject(context.device(), memory);
}

}  // namespace

GpuBuffer createBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                       const char* what) {
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer handle = VK_NULL_HANDLE;
  check(vkCreateBuffer(context.device(), &info, nullptr, &handle), (std::string("creating ") + what).c_str());
  GpuBuffer out;
  out.buffer = BufferObject(context.device(), handle);
  out.size = size;
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(context.device(), handle, &needs);
  const VkMemoryPropertyFlags properties = hostVisible
                                               ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                               : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  out.memory = allocate(context, needs, properties, what);
  check(vkBindBufferMemory(context.device(), handle, out.memory.get(), 0), (std::string("binding memory to ") + what).c_str());
  if (hostVisible)
    check(vkMapMemory(context.device(), out.memory.get(), 0, VK_WHOLE_SIZE, 0, &out.mapped),
          (std::string("mapping ") + what).c_str());
  return out;
}

GpuBuffer uploadBuffer(const VulkanContext& context, VkCommandPool pool, const void* data, VkDeviceSize bytes,
                       VkBufferUsageFlags usage, const char* what) {
  GpuBuffer staging = createBuffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true, "a staging buffer");
  std::memcpy(staging.mapped, data, bytes);
  GpuBuffer out = createBuffer(context, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false, what);
  submitAndWait(context, pool, [&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging.buffer.get(), out.buffer.get(), 1, &region);
  });
  return out;
}

VkImageAspectFlags aspectOf(VkFormat format) {
  switch (format) {
    case VK_FORMAT_S8_UINT:
      return VK_IMAGE_ASPECT_STENCIL_BIT;
    case VK_FORMAT_D16_UNORM_S8_UINT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
      return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    default:
      return VK_IMAGE_ASPECT_COLOR_BIT;
  }
}

VkFormat stencilFormat(VkPhysicalDevice physical) {
  for (VkFormat format : {VK_FORMAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D16_UNORM_S8_UINT}) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(physical, format, &properties);
    if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return format;
  }
  throw VulkanError("choosing a stencil format: the device draws into none", VK_ERROR_FORMAT_NOT_SUPPORTED);
}

GpuImage createImage(const VulkanContext& context, const ImageSpec& spec, const char* what) {
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = spec.format;
  info.extent = {spec.extent.width, spec.extent.height, 1};
  info.mipLevels = spec.mipLevels;
  info.arrayLayers = spec.layers;
  info.samples = spec.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = spec.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage handle = VK_NULL_HANDLE;
  check(vkCreateImage(context.device(), &info, nullptr, &handle), (std::string("creating ") + what).c_str());
  GpuImage out;
  out.image = ImageObject(context.device(), handle);
  out.extent = spec.extent;
  out.layers = spec.layers;
  out.format = spec.format;
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(context.device(), handle, &needs);
  out.memory = allocate(context, needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
  check(vkBindImageMemory(context.device(), handle, out.memory.get(), 0), (std::string("binding memory to ") + what).c_str());
  VkImageViewCreateInfo view{};
  view.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  view.image = handle;
  view.viewType = spec.layers > 1 || spec.arrayView ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  view.format = spec.format;
  view.subresourceRange = {aspectOf(spec.format), 0, spec.mipLevels, 0, spec.layers};
  VkImageView viewHandle = VK_NULL_HANDLE;
  check(vkCreateImageView(context.device(), &view, nullptr, &viewHandle), (std::string("creating a view of ") + what).c_str());
  out.view = ImageViewObject(context.device(), viewHandle);
  return out;
}

void submitAndWait(const VulkanContext& context, VkCommandPool pool, const std::function<void(VkCommandBuffer)>& record) {
  submit(context, pool, record).wait();
}

Submission::Submission(VkDevice device, VkCommandPool pool, VkCommandBuffer cmd, FenceObject fence, GpuBuffer kept)
    : device_(device), pool_(pool), cmd_(cmd), fence_(std::move(fence)), kept_(std::move(kept)) {}

Submission::Submission(Submission&& other) noexcept { *this = std::move(other); }

Submission& Submission::operator=(Submission&& other) noexcept {
  if (this != &other) {
    release();
    device_ = other.device_;
    pool_ = other.pool_;
    cmd_ = std::exchange(other.cmd_, VK_NULL_HANDLE);
    fence_ = std::move(other.fence_);
    kept_ = std::move(other.kept_);
  }
  return *this;
}

Submission::~Submission() { release(); }

void Submission::wait() {
  if (cmd_ == VK_NULL_HANDLE) return;
  const VkFence fence = fence_.get();
  check(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX), "waiting for commands to finish");
  release();
}

void Submission::release() {
  if (cmd_ == VK_NULL_HANDLE) return;
  const VkFence fence = fence_.get();
  vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);  // a destructor: a lost device is not reported here
  vkFreeCommandBuffers(device_, pool_, 1, &cmd_);
  cmd_ = VK_NULL_HANDLE;
  fence_ = FenceObject();
  kept_ = GpuBuffer();
}

Submission submit(const VulkanContext& context, VkCommandPool pool, const std::function<void(VkCommandBuffer)>& record,
                  GpuBuffer kept) {
  VkCommandBufferAllocateInfo allocate{};
  allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  allocate.commandPool = pool;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(context.device(), &allocate, &cmd), "allocating a command buffer");
  struct Free {  // until submitted, the command buffer goes back to the pool however this ends
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    ~Free() {
      if (cmd != VK_NULL_HANDLE) vkFreeCommandBuffers(device, pool, 1, &cmd);
    }
  } free{context.device(), pool, cmd};
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "beginning a command buffer");
  record(cmd);
  check(vkEndCommandBuffer(cmd), "recording a command buffer");
  FenceObject fence = createFence(context.device(), false);
  VkSubmitInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  info.commandBufferCount = 1;
  info.pCommandBuffers = &cmd;
  check(vkQueueSubmit(context.queue(), 1, &info, fence.get()), "submitting commands (vkQueueSubmit)");
  free.cmd = VK_NULL_HANDLE;  // the Submission frees it once the commands are done
  return Submission(context.device(), pool, cmd, std::move(fence), std::move(kept));
}

void transitionImage(VkCommandBuffer cmd, VkImage image, uint32_t layers, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                     VkAccessFlags dstAccess, uint32_t baseMip, uint32_t mipCount) {
  VkImageMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, baseMip, mipCount, 0, layers};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

ShaderModuleObject createShaderModule(VkDevice device, const uint32_t* words, size_t bytes, const char* name) {
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = bytes;
  info.pCode = words;
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(device, &info, nullptr, &module), (std::string("creating shader module ") + name).c_str());
  return ShaderModuleObject(device, module);
}

CommandPoolObject createCommandPool(const VulkanContext& context) {
  VkCommandPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  info.queueFamilyIndex = context.queueFamily();
  VkCommandPool pool = VK_NULL_HANDLE;
  check(vkCreateCommandPool(context.device(), &info, nullptr, &pool), "creating a command pool");
  return CommandPoolObject(context.device(), pool);
}

FenceObject createFence(VkDevice device, bool signaled) {
  VkFenceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  info.flags = signaled ? VK_FENCE_CREATE_SIGNALED_BIT : 0;
  VkFence fence = VK_NULL_HANDLE;
  check(vkCreateFence(device, &info, nullptr, &fence), "creating a fence");
  return FenceObject(device, fence);
}

SemaphoreObject createSemaphore(VkDevice device) {
  VkSemaphoreCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
  VkSemaphore semaphore = VK_NULL_HANDLE;
  check(vkCreateSemaphore(device, &info, nullptr, &semaphore), "creating a semaphore");
  return SemaphoreObject(device, semaphore);
}

}  // namespace ib::vk
