#include "gpu/vulkan_context.h"

#include "gpu/vulkan_check.h"

#include <algorithm>
#include <cstring>
#include <mutex>

namespace ib::vk {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool layerAvailable(const char* name) {
  uint32_t count = 0;
  check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties");
  std::vector<VkLayerProperties> layers(count);
  check(vkEnumerateInstanceLayerProperties(&count, layers.data()), "vkEnumerateInstanceLayerProperties", true);
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) { return !std::strcmp(l.layerName, name); });
}

const char* typeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

// Higher is better; -1 excludes the device under the preference.
int rank(VkPhysicalDeviceType type, DevicePreference preference) {
  const bool cpu = type == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (preference == DevicePreference::kSoftware) return cpu ? 1 : -1;
  if (preference == DevicePreference::kHardware && cpu) return -1;
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
  }
}

// A queue family with graphics that can also present to `surface` (when there is one), or -1.
int graphicsFamily(VkPhysicalDevice device, VkSurfaceKHR surface) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (uint32_t f = 0; f < count; ++f) {
    if (!(families[f].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
    VkBool32 presents = VK_TRUE;
    if (surface) check(vkGetPhysicalDeviceSurfaceSupportKHR(device, f, surface, &presents), "asking whether a queue can present");
    if (presents) return static_cast<int>(f);
  }
  return -1;
}

std::vector<const char*> pointers(const std::vector<std::string>& names) {
  std::vector<const char*> out;
  for (const std::string& n : names) out.push_back(n.c_str());
  return out;
}

}  // namespace

struct VulkanContext::State {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t family = 0;
  VkPhysicalDeviceProperties properties{};
  mutable std::mutex mutex;  // the layer may call back from driver threads
  std::vector<std::string> messages;

  ~State() {
    if (device) vkDestroyDevice(device, nullptr);
    if (surface) vkDestroySurfaceKHR(instance, surface, nullptr);
    if (messenger) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy) destroy(instance, messenger, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
  }

  static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
      auto* self = static_cast<State*>(user);
      std::lock_guard<std::mutex> lock(self->mutex);
      self->messages.push_back(data && data->pMessage ? data->pMessage : "(no message)");
    }
    return VK_FALSE;
  }

  void createInstance(const ContextOptions& options);
  void pickDevice(DevicePreference preference);
  void createDevice(const ContextOptions& options);
};

void VulkanContext::State::createInstance(const ContextOptions& options) {
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "inbetween";
  app.apiVersion = VK_API_VERSION_1_2;
  std::vector<std::string> extensions = options.instanceExtensions;
  std::vector<const char*> layers;
  VkDebugUtilsMessengerCreateInfoEXT debug{};
  debug.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  debug.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  debug.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                      VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  debug.pfnUserCallback = &State::onMessage;
  debug.pUserData = this;
  if (options.validation) {
    if (!layerAvailable(kValidationLayer))
      throw VulkanError("validation requested, but the layer VK_LAYER_KHRONOS_validation is not installed "
                        "(Debian package vulkan-validationlayers)",
                        VK_ERROR_LAYER_NOT_PRESENT);
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  const std::vector<const char*> extensionNames = pointers(extensions);
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensionNames.size());
  info.ppEnabledExtensionNames = extensionNames.data();
  if (options.validation) info.pNext = &debug;  // also reports on instance creation itself
  check(vkCreateInstance(&info, nullptr, &instance), "creating the Vulkan instance (vkCreateInstance)");
  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw VulkanError("vkCreateDebugUtilsMessengerEXT is missing", VK_ERROR_EXTENSION_NOT_PRESENT);
    check(create(instance, &debug, nullptr, &messenger), "creating the validation messenger");
  }
}

void VulkanContext::State::pickDevice(DevicePreference preference) {
  uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "listing Vulkan devices (vkEnumeratePhysicalDevices)");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "listing Vulkan devices", true);
  int best = -1;
  std::string seen;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    seen += std::string(seen.empty() ? "" : ", ") + p.deviceName + " (" + typeName(p.deviceType) + ")";
    const int family = graphicsFamily(d, surface);
    const int score = family < 0 ? -1 : rank(p.deviceType, preference);
    if (score > best) {
      best = score;
      physical = d;
      this->family = static_cast<uint32_t>(family);
      properties = p;
    }
  }
  if (best < 0) {
    const char* wanted = preference == DevicePreference::kSoftware   ? "a software rasterizer (lavapipe)"
                         : preference == DevicePreference::kHardware ? "a hardware GPU"
                                                                     : "any device";
    throw VulkanError(std::string("no Vulkan device with graphics") + (surface ? " that presents to the window" : "") +
                          " matches the request for " + wanted +
                          "; devices found: " + (seen.empty() ? "none (is mesa-vulkan-drivers installed?)" : seen),
                      VK_ERROR_INITIALIZATION_FAILED);
  }
}

void VulkanContext::State::createDevice(const ContextOptions& options) {
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{};
  queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queueInfo.queueFamilyIndex = family;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  const std::vector<const char*> extensions = pointers(options.deviceExtensions);
  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(physical, &info, nullptr, &device),
        ("creating the logical device on " + std::string(properties.deviceName) + " (vkCreateDevice)").c_str());
  vkGetDeviceQueue(device, family, 0, &queue);
}

VulkanContext::VulkanContext(const ContextOptions& options) : state_(std::make_unique<State>()) {
  state_->createInstance(options);
  if (options.createSurface) {
    state_->surface = options.createSurface(state_->instance);
    if (!state_->surface) throw VulkanError("creating the window surface failed", VK_ERROR_INITIALIZATION_FAILED);
  }
  state_->pickDevice(options.device);
  state_->createDevice(options);
}

VulkanContext::~VulkanContext() = default;
VulkanContext::VulkanContext(VulkanContext&&) noexcept = default;
VulkanContext& VulkanContext::operator=(VulkanContext&&) noexcept = default;

VkInstance VulkanContext::instance() const { return state_->instance; }
VkPhysicalDevice VulkanContext::physicalDevice() const { return state_->physical; }
VkDevice VulkanContext::device() const { return state_->device; }
VkQueue VulkanContext::queue() const { return state_->queue; }
uint32_t VulkanContext::queueFamily() const { return state_->family; }
VkSurfaceKHR VulkanContext::surface() const { return state_->surface; }
std::string VulkanContext::deviceName() const { return state_->properties.deviceName; }
bool VulkanContext::software() const { return state_->properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }

std::vector<std::string> VulkanContext::validationMessages() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->messages;
}

}  // namespace ib::vk
