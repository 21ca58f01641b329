// A GLFW window without a client API (Vulkan draws into it), owning GLFW's initialization for its
// lifetime: one window per process, as the player needs. Errors (no display, no Vulkan support in
// GLFW) are WindowErrors that say what failed.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace ib::vk {

class WindowError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct WindowSpec {
  int width = 1280, height = 720;  // screen coordinates
  std::string title = "inbetween";
  bool resizable = true;
};

class GlfwWindow {
 public:
  explicit GlfwWindow(const WindowSpec& spec);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  GLFWwindow* get() const { return window_; }
  // The instance extensions GLFW needs for a surface (VK_KHR_surface and the platform's).
  static std::vector<std::string> requiredExtensions();
  // Makes the window's surface on `instance` (owned by the caller from then on).
  VkSurfaceKHR createSurface(VkInstance instance) const;

  VkExtent2D framebufferSize() const;  // pixels; 0 x 0 while minimized
  bool shouldClose() const;
  void setSize(int width, int height);  // screen coordinates
  void setTitle(const std::string& title);
  // True once after the framebuffer changed size (a resize by the user or setSize), then false.
  bool takeResized();

 private:
  static void onFramebufferSize(GLFWwindow* window, int width, int height);
  GLFWwindow* window_ = nullptr;
  bool resized_ = false;
};

// Processes pending window events (input, resize, close); `wait` blocks until one arrives.
void pollWindowEvents(bool wait = false);

}  // namespace ib::vk
