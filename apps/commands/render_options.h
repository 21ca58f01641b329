// Options of `inbetween render` (and later front ends that draw frames), parsed from the command
// line. Every bad value is an InputError naming the option.
#pragma once

#include "cli.h"
#include "core/png_image.h"
#include "gpu/vulkan_context.h"
#include "pipeline/scene_multimesh.h"
#include "output/canvas.h"
#include "renderers/offscreen_renderer.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ib {

struct RenderOptions {
  std::string output;                  // -o DIR: folder for the frames (created if missing)
  std::optional<std::array<int, 2>> frames;  // --frames A:B, inclusive; default every frame
  std::optional<std::array<int, 2>> size;    // --size WxH; default the canvas at one pixel per drawing pixel
  render::CanvasChoice canvas;               // --canvas drawing|fit|WxH+X+Y; default drawing
  render::OffscreenOptions target;     // --samples, --background (size filled in later)
  render::Overlays overlays;           // --wireframe, --cohesive, --features
  int onion = 0;                       // --onion N: neighbouring frames each side, 0..2
  int sheetEvery = 0;                  // --sheet-every K: every k-th frame on the sheet; 0 = at most 36 tiles
  std::vector<int> sheetFrames;        // --sheet-frames LIST: just these frames on the sheet, ascending; empty = by sheetEvery
  int sheetColumns = 0;                // --sheet-columns N: tiles per row; 0 = about square
  bool preview = false;                // --preview: DIR/preview.png, every frame at tile size, animated (APNG)
  SceneMultimeshOptions mesh;          // --mesh FILE, --no-comesh
  vk::DevicePreference device = vk::DevicePreference::kAny;  // --device any|gpu|cpu
  bool validation = false;             // --validation: Khronos layer on, any message is an error
  int threads = 0;                     // --threads N: solver threads, 0 = all cores
};

// `arguments` holds the options after SCENE; the command name is used in messages.
RenderOptions parseRenderOptions(const cli::Arguments& arguments);

// The Vulkan context for `command`. A missing or broken driver is an InputError (exit 2) that says
// what failed and what to install: the machine is at fault, not inbetween.
vk::VulkanContext openVulkan(const vk::ContextOptions& options, const std::string& command);

// --sampling linear|nearest when given; `option` names it in errors.
std::optional<render::Sampling> parseSampling(const cli::Arguments& arguments, const std::string& option = "--sampling");
// "WxH" with both in [1, 16384]; `option` names it in errors.
std::array<int, 2> parseSize(const std::string& text, const std::string& option);
// "transparent" or a colour "RRGGBB" / "#RRGGBB" / "RRGGBBAA": straight RGBA in [0, 1].
std::array<float, 4> parseBackground(const std::string& text, const std::string& option);

}  // namespace ib
