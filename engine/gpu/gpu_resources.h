// Buffers, images, shader modules and one-off command submission on a VulkanContext. Every object
// is held by a DeviceObject owner; every VkResult goes through check().
#pragma once

#include "gpu/vulkan_context.h"
#include "gpu/vulkan_object.h"

#include <cstddef>
#include <cstdint>
#include <functional>

namespace ib::vk {

// A buffer and its memory. Host-visible buffers are coherent and stay mapped (`mapped` != null).
struct GpuBuffer {
  BufferObject buffer;
  MemoryObject memory;
  void* mapped = nullptr;
  VkDeviceSize size = 0;  // bytes
};

// hostVisible: host-visible coherent memory, mapped for the buffer's lifetime (streamed vertices,
// staging, readback); otherwise device-local (filled through a staging copy). `what` names the
// buffer in errors.
GpuBuffer createBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible,
                       const char* what);

// A device-local buffer holding `bytes`, uploaded through a staging buffer (waits for the copy).
GpuBuffer uploadBuffer(const VulkanContext& context, VkCommandPool pool, const void* data, VkDeviceSize bytes,
                       VkBufferUsageFlags usage, const char* what);

// A 2D image (or 2D array with `layers` > 1) with its memory and one view over all layers.
struct GpuImage {
  ImageObject image;
  MemoryObject memory;
  ImageViewObject view;
  VkExtent2D extent{};
  uint32_t layers = 1;
  VkFormat format = VK_FORMAT_UNDEFINED;
};

struct ImageSpec {
  VkExtent2D extent{};                                  // pixels
  uint32_t layers = 1;                                  // array layers
  bool arrayView = false;                               // view as a 2D array (also for one layer); else
                                                        // 2D for one layer, 2D array for more
  uint32_t mipLevels = 1;                               // mip levels, all in the view
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkImageUsageFlags usage = 0;
};
GpuImage createImage(const VulkanContext& context, const ImageSpec& spec, const char* what);

// Records commands with `record`, submits them to the context's queue and waits for them to finish.
void submitAndWait(const VulkanContext& context, VkCommandPool pool, const std::function<void(VkCommandBuffer)>& record);

// A layout transition of every layer's colour aspect in mip levels [baseMip, baseMip + mipCount),
// with the given stages and accesses.
void transitionImage(VkCommandBuffer cmd, VkImage image, uint32_t layers, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                     VkAccessFlags dstAccess, uint32_t baseMip = 0, uint32_t mipCount = 1);

// A shader module from SPIR-V words (compiled from shaders/ at build time). `name` is for errors.
ShaderModuleObject createShaderModule(VkDevice device, const uint32_t* words, size_t bytes, const char* name);

CommandPoolObject createCommandPool(const VulkanContext& context);  // resettable command buffers
FenceObject createFence(VkDevice device, bool signaled);
SemaphoreObject createSemaphore(VkDevice device);

}  // namespace ib::vk
