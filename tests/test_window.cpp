#include "render_fixtures.h"
#include "renderers/window_presenter.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

using namespace ib;
using namespace ib::render;

namespace {

using Colour = std::array<uint8_t, 4>;

RenderMesh windowScene(const Multimesh& mesh) {
  return renderMeshOf(mesh, {test::paintedImage(64, 64, [](int x, int) { return Colour{uint8_t(4 * x), 60, 160, 255}; }),
                             test::paintedImage(64, 64, [](int, int y) { return Colour{200, uint8_t(4 * y), 40, 255}; })});
}

// Presents `count` frames of the square swaying; returns how many were shown (not skipped).
int presentFrames(WindowPresenter& presenter, const Multimesh& mesh, int count) {
  const Eigen::MatrixX2d X = mesh.keyPositions(0);
  int shown = 0;
  for (int f = 0; f < count; ++f) {
    vk::pollWindowEvents();
    const double t = 0.5 + 0.5 * std::sin(0.7 * f);
    const Eigen::MatrixX2d x = X.rowwise() + Eigen::RowVector2d(6 * t, 0);
    FrameDraw frame;
    frame.positions = &x;
    frame.weights = (Eigen::VectorXd(2) << 1 - t, t).finished();
    frame.view = {0, 0, 64, 64};
    frame.overlays.wireframe = f % 2 == 0;
    shown += presenter.present(frame);
  }
  return shown;
}

// A 320 x 240 window on lavapipe with the validation layer.
WindowOptions testWindow(const char* title, bool resizable) {
  WindowOptions options;
  options.window = {320, 240, title, resizable};
  options.validation = true;
  options.device = vk::DevicePreference::kSoftware;
  return options;
}

}  // namespace

// Hidden from the plain run (it needs an X server); ctest runs it under xvfb-run.
TEST_CASE("window: frames present, a resize rebuilds the swapchain, validation stays silent", "[.window]") {
  const Multimesh mesh = test::squareGrid(6, 8, 8, 48, 2);
  const RenderMesh scene = windowScene(mesh);
  WindowOptions options = testWindow("inbetween test", true);
  options.vsync = false;
  WindowPresenter presenter(scene, options);
  CHECK(presentFrames(presenter, mesh, 6) >= 5);
  CHECK(presenter.extent().width == 320);
  CHECK(presenter.extent().height == 240);

  presenter.window().setSize(480, 300);
  for (int tries = 0; tries < 200; ++tries) {  // the X server applies the resize asynchronously
    vk::pollWindowEvents();
    const VkExtent2D size = presenter.window().framebufferSize();
    if (size.width == 480 && size.height == 300) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  CHECK(presentFrames(presenter, mesh, 6) >= 5);
  CHECK(presenter.extent().width == 480);
  CHECK(presenter.extent().height == 300);
  CHECK(presenter.rebuilds() >= 1);
  const std::vector<std::string> messages = presenter.context().validationMessages();
  INFO((messages.empty() ? std::string() : messages.front()));
  CHECK(messages.empty());
}

// The capture of a frame shows the backdrop, the mesh's artwork and what the overlay drew on top,
// each where it was drawn.
TEST_CASE("window: a captured frame holds the checkerboard, the artwork and the overlay drawn after it", "[.window]") {
  const Multimesh mesh = test::squareGrid(6, 8, 8, 48, 2);
  const RenderMesh scene = windowScene(mesh);
  WindowPresenter presenter(scene, testWindow("inbetween capture test", false));
  REQUIRE(presenter.canCapture());
  Backdrop backdrop;
  backdrop.colour = {1, 1, 1};
  backdrop.second = {0, 0, 0};
  backdrop.checkerboard = true;
  backdrop.square = 10;
  presenter.setBackdrop(backdrop);
  const Eigen::MatrixX2d x = mesh.keyPositions(0);
  FrameDraw frame;
  frame.positions = &x;
  frame.weights = (Eigen::VectorXd(2) << 1, 0).finished();
  frame.view = {0, 0, 64, 64};  // widened to 85.3 x 64 about its centre: the mesh at x 8..56 is px 70..250
  const Overlay overlay = [](VkCommandBuffer cmd) {  // a UI panel: a red rectangle in the top-left corner
    VkClearAttachment clear{};
    clear.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    clear.clearValue.color = {{1, 0, 0, 1}};
    const VkClearRect rect{{{0, 0}, {40, 30}}, 0, 1};
    vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
  };
  RgbaImage shot;
  bool captured = false;
  for (int tries = 0; tries < 5 && !captured; ++tries) {
    vk::pollWindowEvents();
    captured = presenter.present(frame, overlay, &shot);
  }
  REQUIRE(captured);
  REQUIRE(shot.width == 320);
  REQUIRE(shot.height == 240);
  auto near = [&](int px, int py, Colour want) {  // within 2/255 per channel
    const uint8_t* p = shot.at(px, py);
    INFO("pixel " << px << "," << py << ": " << int(p[0]) << " " << int(p[1]) << " " << int(p[2]));
    for (int c = 0; c < 3; ++c) CHECK(std::abs(int(p[c]) - int(want[c])) <= 2);
  };
  near(5, 5, {255, 0, 0, 255});     // the overlay, drawn after the mesh and the backdrop
  near(45, 5, {255, 255, 255, 255});  // square (4, 0) of the checkerboard: first colour
  near(55, 5, {0, 0, 0, 255});        // square (5, 0): second colour
  near(160, 120, {uint8_t(4 * 32), 60, 160, 255});  // key 0's artwork at drawing pixel (32, 32)
  const std::vector<std::string> messages = presenter.context().validationMessages();
  INFO((messages.empty() ? std::string() : messages.front()));
  CHECK(messages.empty());
}

TEST_CASE("window: without a display the error says so") {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  const std::string savedDisplay = display ? display : "", savedWayland = wayland ? wayland : "";
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  const Multimesh mesh = test::squareGrid(6, 8, 8, 48, 2);
  const RenderMesh scene = windowScene(mesh);
  CHECK_THROWS_WITH(WindowPresenter(scene, WindowOptions{}), Catch::Contains("cannot open a window"));
  if (display) setenv("DISPLAY", savedDisplay.c_str(), 1);
  if (wayland) setenv("WAYLAND_DISPLAY", savedWayland.c_str(), 1);
}
