// Vulkan results as errors that say what failed and why (vk-bootstrap style): every VkResult a
// call returns goes through check(), which throws VulkanError naming the call and the result.
#pragma once

#include <stdexcept>
#include <string>
#include <vulkan/vulkan.h>

namespace ib::vk {

// A Vulkan call failed. result() is the VkResult it returned.
class VulkanError : public std::runtime_error {
 public:
  VulkanError(const std::string& what, VkResult result) : std::runtime_error(what), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

// The result's name and what it means, e.g. "VK_ERROR_OUT_OF_DEVICE_MEMORY (the device ran out of memory)".
std::string describe(VkResult result);

// Throws VulkanError("<what> failed: <describe(result)>") unless result is VK_SUCCESS (or, for
// calls that may return them, VK_INCOMPLETE / VK_SUBOPTIMAL_KHR when `allowPartial`).
void check(VkResult result, const char* what, bool allowPartial = false);

}  // namespace ib::vk
