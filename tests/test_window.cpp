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

}  // namespace

// Hidden from the plain run (it needs an X server); ctest runs it under xvfb-run.
TEST_CASE("window: frames present, a resize rebuilds the swapchain, validation stays silent", "[.window]") {
  const Multimesh mesh = test::squareGrid(6, 8, 8, 48, 2);
  const RenderMesh scene = windowScene(mesh);
  WindowOptions options;
  options.window = {320, 240, "inbetween test", true};
  options.validation = true;
  options.device = vk::DevicePreference::kSoftware;
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
