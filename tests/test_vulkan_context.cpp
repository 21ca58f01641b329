#include "gpu/vulkan_check.h"
#include "gpu/vulkan_context.h"

#include <catch2/catch.hpp>

using namespace ib::vk;

TEST_CASE("vulkan context: headless lavapipe comes up with the validation layer silent") {
  ContextOptions options;
  options.validation = true;
  options.device = DevicePreference::kSoftware;
  const VulkanContext context(options);
  INFO("device " << context.deviceName());
  CHECK(context.software());
  CHECK(context.device() != VK_NULL_HANDLE);
  CHECK(context.queue() != VK_NULL_HANDLE);
  CHECK(context.validationMessages().empty());
}

TEST_CASE("vulkan context: a preference no device meets is an error listing the devices seen") {
  // This machine has no hardware GPU (CI runs on lavapipe); with one, the context simply comes up.
  ContextOptions options;
  options.device = DevicePreference::kHardware;
  try {
    const VulkanContext context(options);
    CHECK(!context.software());
  } catch (const VulkanError& e) {
    CHECK_THAT(e.what(), Catch::Contains("no Vulkan device with graphics matches the request for a hardware GPU") &&
                             Catch::Contains("llvmpipe"));
  }
}

TEST_CASE("vulkan check: a failed result names the call and what the result means") {
  CHECK_NOTHROW(check(VK_SUCCESS, "vkNothing"));
  CHECK_NOTHROW(check(VK_INCOMPLETE, "vkList", true));
  CHECK_THROWS_WITH(check(VK_ERROR_OUT_OF_DEVICE_MEMORY, "allocating the vertex buffer"),
                    "allocating the vertex buffer failed: VK_ERROR_OUT_OF_DEVICE_MEMORY (the device ran out of memory)");
}
