#include "renderers/render_job.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "gpu/vulkan_check.h"
#include "gpu/vulkan_context.h"
#include "multimesh/multimesh.h"
#include "output/animated_png.h"
#include "output/contact_sheet.h"
#include "output/onion_window.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>

namespace ib::render {

namespace {

// The offscreen target; a size the device has no memory for is the user's size, not an internal error.
OffscreenRenderer makeRenderer(const vk::VulkanContext& context, const RenderMesh& mesh, const OffscreenOptions& target) {
  try {
    return OffscreenRenderer(context, mesh, target);
  } catch (const vk::VulkanError& e) {
    if (e.result() != VK_ERROR_OUT_OF_DEVICE_MEMORY && e.result() != VK_ERROR_OUT_OF_HOST_MEMORY) throw;
    throw InputError("--size " + std::to_string(target.width) + "x" + std::to_string(target.height) + ": " +
                     context.deviceName() + " has not enough memory for a target of that size with " +
                     std::to_string(target.samples) + " samples (" + e.what() + "): choose a smaller --size or fewer --samples");
  }
}

}  // namespace

std::string framePath(const std::string& folder, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", frame);
  return (std::filesystem::path(folder) / name).string();
}

RenderJobReport renderFrames(const vk::VulkanContext& context, const Scene& scene, const Multimesh& mesh,
                             std::vector<RgbaImage> drawings, const std::vector<int>& features,
                             const RenderJobOptions& options, const JobProgress& progress) {
  const int frameCount = scene.timeline.frameCount();
  const int first = options.frames[0], last = options.frames[1];
  if (first < 0 || first > last || last >= frameCount)
    throw InputError("frames " + std::to_string(first) + ".." + std::to_string(last) + " are not in the timeline's 0.." +
                     std::to_string(frameCount - 1));
  for (const int f : options.sheetFrames)
    if (f < first || f > last)
      throw InputError("sheet frame " + std::to_string(f) + " is not rendered (frames " + std::to_string(first) + ".." +
                       std::to_string(last) + ")");
  int canvasW = 0, canvasH = 0;
  for (const RgbaImage& d : drawings) {
    canvasW = std::max(canvasW, d.width);
    canvasH = std::max(canvasH, d.height);
  }
  RenderMesh renderMesh = renderMeshOf(mesh, std::move(drawings), features);
  if (!scene.cutInk) renderMesh.inks = {};
  FrameStream stream = sceneFrameStream(scene, mesh, options.solving);
  const ViewBox drawingCanvas{0, 0, double(canvasW), double(canvasH)};
  ViewBox animation = drawingCanvas;
  if (options.canvas.kind == CanvasChoice::Kind::kFit) {
    animation = {INFINITY, INFINITY, -INFINITY, -INFINITY};  // grown by every rendered frame's positions
    while (!stream.done() && stream.nextFrame() <= last) {
      if (progress) progress("measuring the animation's bounds, frame " + std::to_string(stream.nextFrame()), 0);
      const AnimationFrame frame = stream.next();
      if (frame.index < first) continue;
      animation = {std::min(animation.x0, frame.x.col(0).minCoeff()), std::min(animation.y0, frame.x.col(1).minCoeff()),
                   std::max(animation.x1, frame.x.col(0).maxCoeff()), std::max(animation.y1, frame.x.col(1).maxCoeff())};
    }
    stream.restart();
  }
  RenderJobReport report;
  report.canvas = canvasBox(options.canvas, drawingCanvas, animation);
  OffscreenOptions target = options.target;
  if (target.width == 0 && target.height == 0) {
    const std::array<int, 2> pixels = canvasPixels(report.canvas);
    target.width = pixels[0];
    target.height = pixels[1];
  }
  OffscreenRenderer renderer = makeRenderer(context, renderMesh, target);
  const int width = target.width, height = target.height;
  report.width = width;
  report.height = height;
  const ViewBox view = fitView(report.canvas, width, height, 0);

  const int rendered = last - first + 1;
  const int every = options.sheetEvery > 0 ? options.sheetEvery : (rendered + 35) / 36;
  const auto onSheet = [&](int f) {
    if (!options.sheetFrames.empty()) return std::binary_search(options.sheetFrames.begin(), options.sheetFrames.end(), f);
    return (f - first) % every == 0;
  };
  const int tileW = std::min(240, width);
  const int tileH = std::max(1, static_cast<int>(std::lround(double(tileW) * height / width)));
  std::vector<RgbaImage> tiles, preview;
  std::deque<int> inFlight;  // frame indices submitted, oldest first
  const auto started = std::chrono::steady_clock::now();
  const auto collect = [&] {
    const int f = inFlight.front();
    inFlight.pop_front();
    const RgbaImage image = renderer.take();
    writePng(framePath(options.folder, f), image);
    const bool sheet = onSheet(f);
    if (sheet || options.preview) {
      RgbaImage tile = shrink(image, tileW, tileH);
      if (sheet) tiles.push_back(tile);
      if (options.preview) preview.push_back(std::move(tile));
    }
    ++report.written;
    if (progress)
      progress("rendering frame " + std::to_string(f) + " (" + std::to_string(report.written) + " of " +
                   std::to_string(rendered) + ")",
               double(report.written) / rendered);
  };
  OnionStyle onion;
  onion.neighbours = options.onion;
  playWithNeighbours(stream, options.frames, options.onion, [&](const std::deque<AnimationFrame>& window, size_t at) {
    report.reach.add(window[at].index, window[at].x, view);
    FrameDraw request = frameWithOnionSkins(window, at, onion, view, options.overlays);
    request.sampling = options.sampling;
    renderer.submit(request);
    inFlight.push_back(window[at].index);
    while (static_cast<int>(inFlight.size()) > 2) collect();
  });
  while (!inFlight.empty()) collect();
  report.sheet = (std::filesystem::path(options.folder) / "contact_sheet.png").string();
  ContactSheetOptions sheet;
  sheet.columns = options.sheetColumns;
  writePng(report.sheet, contactSheet(tiles, sheet));
  if (options.preview) {
    report.preview = (std::filesystem::path(options.folder) / "preview.png").string();
    writeFileAtomically(report.preview, encodeAnimatedPng(preview, static_cast<int>(std::lround(1000 / scene.timeline.fps()))));
  }
  report.firstFrame = framePath(options.folder, first);
  report.lastFrame = framePath(options.folder, last);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return report;
}

}  // namespace ib::render
