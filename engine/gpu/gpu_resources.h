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

// The aspects of `format`: stencil (and depth) for the depth/stencil formats, colour otherwise.
VkImageAspectFlags aspectOf(VkFormat format);

// The stencil format this device draws into with optimal tiling: S8_UINT where it can, else a
// combined depth/stencil format. Throws VulkanError when it has none.
VkFormat stencilFormat(VkPhysicalDevice physical);

// Records commands with `record`, submits them to the context's queue and waits for them to finish.
void submitAndWait(const VulkanContext& context, VkCommandPool pool, const std::function<void(VkCommandBuffer)>& record);

// Commands submitted without waiting for them: they run on the queue while the caller goes on, and
// later submissions to the queue see their results through the barriers they record. Keeps the
// buffer they read (e.g. a staging buffer) until they are done; destroying it waits for them and
// frees the command buffer (on the thread that owns `pool`). Move-only.
class Submission {
 public:
  Submission() = default;
  Submission(VkDevice device, VkCommandPool pool, VkCommandBuffer cmd, FenceObject fence, GpuBuffer kept);
  Submission(Submission&& other) noexcept;
  Submission& operator=(Submission&& other) noexcept;
  Submission(const Submission&) = delete;
  Submission& operator=(const Submission&) = delete;
  ~Submission();
  void wait();        // until they have (VulkanError for a lost device), then frees what it holds

 private:
  void release();  // waits, then frees the command buffer and what it keeps
  VkDevice device_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  FenceObject fence_;
  GpuBuffer kept_;
};
// Records commands with `record` and submits them to the context's queue; `kept` lives until they finish.
Submission submit(const VulkanContext& context, VkCommandPool pool, const std::function<void(VkCommandBuffer)>& record,
                  GpuBuffer kept = {});

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
