#include "gpu/vulkan_check.h"

namespace ib::vk {

std::string describe(VkResult result) {
  switch (result) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_INCOMPLETE: return "VK_INCOMPLETE (more results than room for them)";
    case VK_SUBOPTIMAL_KHR: return "VK_SUBOPTIMAL_KHR (the swapchain no longer matches the surface)";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY (the host ran out of memory)";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY (the device ran out of memory)";
    case VK_ERROR_INITIALIZATION_FAILED:
      return "VK_ERROR_INITIALIZATION_FAILED (the driver could not initialize; is a Vulkan driver installed?)";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST (the device hung or was reset)";
    case VK_ERROR_MEMORY_MAP_FAILED: return "VK_ERROR_MEMORY_MAP_FAILED";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT (a requested layer is not installed)";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT (a requested extension is not supported)";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT (a requested feature is not supported)";
    case VK_ERROR_INCOMPATIBLE_DRIVER:
      return "VK_ERROR_INCOMPATIBLE_DRIVER (no driver supports the requested Vulkan version; is a Vulkan driver installed?)";
    case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
    case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    case VK_ERROR_SURFACE_LOST_KHR: return "VK_ERROR_SURFACE_LOST_KHR (the window's surface is gone)";
    case VK_ERROR_NATIVE_WINDOW_IN_USE_KHR: return "VK_ERROR_NATIVE_WINDOW_IN_USE_KHR";
    case VK_ERROR_OUT_OF_DATE_KHR: return "VK_ERROR_OUT_OF_DATE_KHR (the swapchain must be rebuilt)";
    default: return "VkResult " + std::to_string(static_cast<int>(result));
  }
}

void check(VkResult result, const char* what, bool allowPartial) {
  if (result == VK_SUCCESS) return;
  if (allowPartial && (result == VK_INCOMPLETE || result == VK_SUBOPTIMAL_KHR)) return;
  throw VulkanError(std::string(what) + " failed: " + describe(result), result);
}

}  // namespace ib::vk
