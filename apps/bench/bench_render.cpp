// `inbetween bench render`: headless frames per second of the renderer (two keys' artwork blended
// on a deforming strip, MSAA, read back to RGBA), one JSON line per mesh size.
#include "bench/bench.h"

#include "commands/render_options.h"
#include "core/error.h"
#include "renderers/offscreen_renderer.h"
#include "testkit/shape_generators.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench render [--triangles LIST] [--size WxH] [--frames N] [--samples N] [--device D]\n"
    "\n"
    "Renders a strip of about T triangles with two keys (rest and bent), each with its own 1024x256\n"
    "artwork, blended by weights that change every frame while the vertices move, and reads every\n"
    "frame back to RGBA, frames pipelined as `inbetween render` does. One JSON line per size: device,\n"
    "triangles, width, height, samples, frames, fps, ms_per_frame.\n"
    "\n"
    "  --triangles LIST  comma-separated triangle counts, k = 1000 (default 1k,10k)\n"
    "  --size WxH        picture size (default 1280x720)\n"
    "  --frames N        frames timed per size, after 5 untimed (default 120)\n"
    "  --samples N       MSAA samples (default 4)\n"
    "  --device D        any, gpu or cpu (default cpu: lavapipe, comparable across machines)\n";

// Artwork of key `key`: stripes (key 0) or a checkerboard (key 1) in two colours, opaque.
RgbaImage artwork(int key) {
  RgbaImage image;
  image.width = 1024;
  image.height = 256;
  image.pixels.resize(static_cast<size_t>(image.width) * image.height * 4);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const bool on = key == 0 ? (x / 32) % 2 == 0 : ((x / 32) + (y / 32)) % 2 == 0;
      uint8_t* p = image.at(x, y);
      p[0] = on ? 230 : 30;
      p[1] = key == 0 ? 120 : 200;
      p[2] = on ? 40 : 220;
      p[3] = 255;
    }
  return image;
}

// The strip's render mesh: each key's UVs are its positions normalized to its bounding box.
render::RenderMesh stripScene(const Multimesh& mesh) {
  render::RenderMesh scene = render::renderMeshOf(mesh, {artwork(0), artwork(1)});
  for (int k = 0; k < 2; ++k) {
    const Eigen::MatrixX2d X = mesh.keyPositions(k);
    const Eigen::RowVector2d lo = X.colwise().minCoeff(), span = X.colwise().maxCoeff() - lo;
    scene.keyUV[k] = ((X.rowwise() - lo).array().rowwise() / span.array()).matrix().cast<float>();
  }
  return scene;
}

nlohmann::json benchSize(const vk::VulkanContext& context, int triangles, const render::OffscreenOptions& target, int frames) {
  // The 4:1 strip has about 1.72 triangles per vertex at 1k triangles, nearing 2 as it grows.
  const Multimesh mesh = benchmarkStrip(std::max(16, static_cast<int>(triangles / (triangles < 5000 ? 1.72 : 1.93))), 2);
  const render::RenderMesh scene = stripScene(mesh);
  render::OffscreenRenderer renderer(context, scene, target);
  const Eigen::MatrixX2d X0 = mesh.keyPositions(0), X1 = mesh.keyPositions(1);
  const render::ViewBox view = render::fitView(render::boundsOf({X0, X1}), target.width, target.height);
  Eigen::MatrixX2d x;  // copied into the frame's vertex stream by submit()
  auto frame = [&](int f) {
    const double t = 0.05 + 0.9 * (0.5 + 0.5 * std::sin(0.1 * f));  // both keys always in play
    x = (1 - t) * X0 + t * X1;
    render::FrameDraw draw;
    draw.positions = &x;
    draw.weights = (Eigen::VectorXd(2) << 1 - t, t).finished();
    draw.view = view;
    renderer.submit(draw);
    if (renderer.pending() >= target.framesInFlight) renderer.take();
  };
  const int warmup = 5;
  for (int f = 0; f < warmup; ++f) frame(f);
  while (renderer.pending() > 0) renderer.take();
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) frame(warmup + f);
  while (renderer.pending() > 0) renderer.take();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {{"device", context.deviceName()}, {"triangles", mesh.triangleCount()},
          {"vertices", mesh.vertexCount()}, {"width", target.width},     {"height", target.height},
          {"samples", static_cast<int>(renderer.samples())}, {"frames", frames}, {"fps", frames / seconds},
          {"ms_per_frame", 1000 * seconds / frames}};
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::vector<int> sizes = cli::integerList(a.value("triangles", "1k,10k"), "triangles", 16, 4000000);
  const std::array<int, 2> size = parseSize(a.value("size", "1280x720"), "--size");
  render::OffscreenOptions target;
  target.width = size[0];
  target.height = size[1];
  target.samples = a.integer("samples", 4, 1, 64);
  target.background = {1, 1, 1, 1};
  const int frames = a.integer("frames", 120, 1, 100000);
  vk::ContextOptions options;
  const std::string device = a.value("device", "cpu");
  if (device == "gpu") options.device = vk::DevicePreference::kHardware;
  else if (device == "cpu") options.device = vk::DevicePreference::kSoftware;
  else if (device != "any") throw InputError("--device: '" + device + "' is not any, gpu or cpu");
  const vk::VulkanContext context = openVulkan(options, "bench render");
  for (int triangles : sizes) output.printLine(benchSize(context, triangles, target, frames));
}

}  // namespace

Benchmark renderBenchmark() {
  return {"render", "headless rendering (frames per second)", kUsage, {"triangles", "size", "frames", "samples", "device"},
          {}, run};
}

}  // namespace ib
