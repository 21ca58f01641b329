#include "player/imgui_layer.h"

#include "gpu/vulkan_check.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

namespace ib::play {

namespace {

void checkImGuiVulkan(VkResult result) { vk::check(result, "Dear ImGui's Vulkan backend"); }

}  // namespace

ImGuiLayer::ImGuiLayer(render::WindowPresenter& presenter, void* userData) {
  IMGUI_CHECKVERSION();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is the player's, not a file's
  io.UserData = userData;
  applyPlayerStyle();
  try {
    glfw_ = ImGui_ImplGlfw_InitForVulkan(presenter.window().get(), true);
    const render::OverlayTarget target = presenter.overlayTarget();
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = target.instance;
    info.PhysicalDevice = target.physicalDevice;
    info.Device = target.device;
    info.QueueFamily = target.queueFamily;
    info.Queue = target.queue;
    info.DescriptorPool = target.descriptorPool;
    info.MinImageCount = target.minImageCount;
    info.ImageCount = target.imageCount;
    info.MSAASamples = target.samples;
    info.CheckVkResultFn = &checkImGuiVulkan;
    vulkan_ = ImGui_ImplVulkan_Init(&info, target.renderPass);
    if (!glfw_ || !vulkan_) throw vk::VulkanError("Dear ImGui's backends did not start", VK_ERROR_INITIALIZATION_FAILED);
    presenter.submitOnce([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
  } catch (...) {
    shutdown();
    throw;
  }
}

ImGuiLayer::~ImGuiLayer() { shutdown(); }

void ImGuiLayer::shutdown() {
  if (!context_) return;
  ImGui::SetCurrentContext(context_);
  if (vulkan_) ImGui_ImplVulkan_Shutdown();
  if (glfw_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext(context_);
  context_ = nullptr;
  vulkan_ = glfw_ = false;
}

void ImGuiLayer::beginFrame() {
  ImGui::SetCurrentContext(context_);
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

render::Overlay ImGuiLayer::endFrame() {
  ImGui::Render();
  ImDrawData* data = ImGui::GetDrawData();
  return [data](VkCommandBuffer cmd) { ImGui_ImplVulkan_RenderDrawData(data, cmd); };
}

void ImGuiLayer::skipFrame() { ImGui::EndFrame(); }

void applyPlayerStyle() {
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 4;
  style.FrameRounding = 3;
  style.GrabRounding = 3;
  style.GrabMinSize = 8;
  style.TabRounding = 3;
  style.ScrollbarRounding = 3;
  style.WindowBorderSize = 1;
  style.FramePadding = ImVec2(6, 3);
  style.ItemSpacing = ImVec2(6, 5);
  ImVec4* colours = style.Colors;
  const ImVec4 accent(0.96f, 0.55f, 0.18f, 1.00f);  // orange, as animation tools mark the playhead
  colours[ImGuiCol_WindowBg] = ImVec4(0.13f, 0.14f, 0.16f, 1.00f);
  colours[ImGuiCol_ChildBg] = ImVec4(0.10f, 0.11f, 0.12f, 1.00f);
  colours[ImGuiCol_TitleBg] = colours[ImGuiCol_TitleBgActive] = ImVec4(0.09f, 0.10f, 0.11f, 1.00f);
  colours[ImGuiCol_FrameBg] = ImVec4(0.20f, 0.21f, 0.24f, 1.00f);
  colours[ImGuiCol_FrameBgHovered] = ImVec4(0.26f, 0.27f, 0.31f, 1.00f);
  colours[ImGuiCol_FrameBgActive] = ImVec4(0.30f, 0.31f, 0.36f, 1.00f);
  colours[ImGuiCol_SliderGrab] = accent;
  colours[ImGuiCol_SliderGrabActive] = ImVec4(1.00f, 0.66f, 0.30f, 1.00f);
  colours[ImGuiCol_CheckMark] = accent;
  colours[ImGuiCol_Button] = ImVec4(0.22f, 0.23f, 0.27f, 1.00f);
  colours[ImGuiCol_ButtonHovered] = ImVec4(0.30f, 0.32f, 0.37f, 1.00f);
  colours[ImGuiCol_ButtonActive] = ImVec4(0.55f, 0.34f, 0.14f, 1.00f);
  colours[ImGuiCol_Header] = ImVec4(0.22f, 0.23f, 0.27f, 1.00f);
  colours[ImGuiCol_HeaderHovered] = ImVec4(0.30f, 0.32f, 0.37f, 1.00f);
  colours[ImGuiCol_HeaderActive] = ImVec4(0.55f, 0.34f, 0.14f, 1.00f);
  colours[ImGuiCol_Tab] = ImVec4(0.16f, 0.17f, 0.19f, 1.00f);
  colours[ImGuiCol_TabHovered] = ImVec4(0.30f, 0.32f, 0.37f, 1.00f);
  colours[ImGuiCol_TabActive] = ImVec4(0.27f, 0.28f, 0.33f, 1.00f);
  colours[ImGuiCol_PlotLines] = accent;
  colours[ImGuiCol_PlotHistogram] = accent;
}

}  // namespace ib::play
