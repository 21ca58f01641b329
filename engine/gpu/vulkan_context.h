// The Vulkan instance, physical device, logical device and graphics queue, headless by default
// (vk-bootstrap style: headless is a plain option, errors say what failed and why). With
// validation on, the Khronos validation layer's warnings and errors are collected, so tests can
// require silence.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

namespace ib::vk {

enum class DevicePreference {
  kAny,       // a hardware GPU when there is one, else a software rasterizer (lavapipe). Default
  kHardware,  // a hardware GPU only
  kSoftware,  // a software rasterizer only (lavapipe): the same pixels on every machine
};

struct ContextOptions {
  bool validation = false;                       // enable VK_LAYER_KHRONOS_validation; default off
  DevicePreference device = DevicePreference::kAny;
  std::vector<std::string> instanceExtensions;   // e.g. GLFW's surface extensions; empty = headless
  std::vector<std::string> deviceExtensions;     // e.g. VK_KHR_swapchain for a window; default none
  // For a window: makes the surface once the instance exists (e.g. with glfwCreateWindowSurface).
  // The context then owns it and picks a device whose graphics queue can present to it. Default none.
  std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

// Owns the instance, the debug messenger and the device; destroys them in reverse order. Move-only
// (the messenger's callback points at heap state, which moves with the owner).
class VulkanContext {
 public:
  // Throws VulkanError naming the failed step: no Vulkan loader or driver, no device matching the
  // preference (listing the devices seen), the validation layer missing.
  explicit VulkanContext(const ContextOptions& options = {});
  ~VulkanContext();
  VulkanContext(VulkanContext&&) noexcept;
  VulkanContext& operator=(VulkanContext&&) noexcept;
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const;
  VkPhysicalDevice physicalDevice() const;
  VkDevice device() const;
  VkQueue queue() const;          // graphics (and transfer) queue
  uint32_t queueFamily() const;
  VkSurfaceKHR surface() const;   // VK_NULL_HANDLE when headless
  std::string deviceName() const;
  bool software() const;          // a CPU rasterizer (VK_PHYSICAL_DEVICE_TYPE_CPU)
  // Validation warnings and errors so far (empty without validation).
  std::vector<std::string> validationMessages() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ib::vk
