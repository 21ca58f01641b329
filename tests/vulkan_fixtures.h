// The Vulkan context the renderer tests draw with.
#pragma once

#include "gpu/vulkan_context.h"

namespace ib::test {

// Headless lavapipe with VK_LAYER_KHRONOS_validation: tests require validationMessages() empty.
inline vk::VulkanContext validatedContext() {
  vk::ContextOptions options;
  options.validation = true;
  options.device = vk::DevicePreference::kSoftware;
  return vk::VulkanContext(options);
}

}  // namespace ib::test
