// One move-only owner per Vulkan device object (Vulkan-Samples style): it holds the device and the
// handle and calls the matching vkDestroy*/vkFree* exactly once, when it goes out of scope or is
// reset. Objects are created by the caller (every VkResult through check()) and then adopted:
//   DeviceObject<VkBuffer, vkDestroyBuffer> buffer(device, handle);
#pragma once

#include <utility>
#include <vulkan/vulkan.h>

namespace ib::vk {

template <typename Handle, auto Destroy>
class DeviceObject {
 public:
  DeviceObject() = default;
  DeviceObject(VkDevice device, Handle handle) : device_(device), handle_(handle) {}
  ~DeviceObject() { reset(); }
  DeviceObject(DeviceObject&& other) noexcept
      : device_(other.device_), handle_(std::exchange(other.handle_, Handle(VK_NULL_HANDLE))) {}
  DeviceObject& operator=(DeviceObject&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, Handle(VK_NULL_HANDLE));
    }
    return *this;
  }
  DeviceObject(const DeviceObject&) = delete;
  DeviceObject& operator=(const DeviceObject&) = delete;

  Handle get() const { return handle_; }
  explicit operator bool() const { return handle_ != Handle(VK_NULL_HANDLE); }
  void reset() {
    if (handle_ != Handle(VK_NULL_HANDLE)) Destroy(device_, handle_, nullptr);
    handle_ = Handle(VK_NULL_HANDLE);
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = Handle(VK_NULL_HANDLE);
};

using BufferObject = DeviceObject<VkBuffer, vkDestroyBuffer>;
using MemoryObject = DeviceObject<VkDeviceMemory, vkFreeMemory>;
using ImageObject = DeviceObject<VkImage, vkDestroyImage>;
using ImageViewObject = DeviceObject<VkImageView, vkDestroyImageView>;
using SamplerObject = DeviceObject<VkSampler, vkDestroySampler>;
using ShaderModuleObject = DeviceObject<VkShaderModule, vkDestroyShaderModule>;
using PipelineObject = DeviceObject<VkPipeline, vkDestroyPipeline>;
using PipelineLayoutObject = DeviceObject<VkPipelineLayout, vkDestroyPipelineLayout>;
using DescriptorSetLayoutObject = DeviceObject<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using DescriptorPoolObject = DeviceObject<VkDescriptorPool, vkDestroyDescriptorPool>;
using RenderPassObject = DeviceObject<VkRenderPass, vkDestroyRenderPass>;
using FramebufferObject = DeviceObject<VkFramebuffer, vkDestroyFramebuffer>;
using CommandPoolObject = DeviceObject<VkCommandPool, vkDestroyCommandPool>;
using FenceObject = DeviceObject<VkFence, vkDestroyFence>;
using SemaphoreObject = DeviceObject<VkSemaphore, vkDestroySemaphore>;

}  // namespace ib::vk
