#include "gpu/glfw_window.h"

#include "gpu/vulkan_check.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

namespace ib::vk {

namespace {

std::string lastGlfwError() {
  const char* description = nullptr;
  const int code = glfwGetError(&description);
  return code == GLFW_NO_ERROR ? std::string("no details") : std::string(description ? description : "unknown error");
}

}  // namespace

GlfwWindow::GlfwWindow(const WindowSpec& spec) {
  if (!glfwInit())
    throw WindowError("cannot open a window: GLFW could not initialize (" + lastGlfwError() +
                      "); is DISPLAY or WAYLAND_DISPLAY set? Headless rendering needs no window");
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw WindowError("cannot open a window: GLFW found no Vulkan loader");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, spec.resizable ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(spec.width, spec.height, spec.title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = lastGlfwError();
    glfwTerminate();
    throw WindowError("cannot open a window: " + why);
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetFramebufferSizeCallback(window_, &GlfwWindow::onFramebufferSize);
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<std::string> GlfwWindow::requiredExtensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw WindowError("GLFW cannot make Vulkan surfaces here: " + lastGlfwError());
  return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR GlfwWindow::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  check(glfwCreateWindowSurface(instance, window_, nullptr, &surface), "creating the window surface (glfwCreateWindowSurface)");
  return surface;
}

VkExtent2D GlfwWindow::framebufferSize() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return {static_cast<uint32_t>(width), static_cast<uint32_t>(height)};
}

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::setSize(int width, int height) { glfwSetWindowSize(window_, width, height); }
void GlfwWindow::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

bool GlfwWindow::takeResized() {
  const bool resized = resized_;
  resized_ = false;
  return resized;
}

void GlfwWindow::onFramebufferSize(GLFWwindow* window, int, int) {
  static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window))->resized_ = true;
}

void pollWindowEvents(bool wait) {
  if (wait) glfwWaitEvents();
  else glfwPollEvents();
}

}  // namespace ib::vk
