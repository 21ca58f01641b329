#include "commands/render_options.h"

#include "core/error.h"
#include "gpu/vulkan_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace ib {

namespace {

int parseCount(const std::string& text, const std::string& option, int min, int max) {
  if (text.empty() || text.size() > 9 || !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    throw InputError(option + ": '" + text + "' is not a whole number");
  const int value = std::atoi(text.c_str());
  if (value < min || value > max)
    throw InputError(option + ": " + text + " is outside " + std::to_string(min) + ".." + std::to_string(max));
  return value;
}

}  // namespace

vk::VulkanContext openVulkan(const vk::ContextOptions& options, const std::string& command) {
  try {
    return vk::VulkanContext(options);
  } catch (const vk::VulkanError& e) {
    throw InputError(command + ": no usable Vulkan device: " + e.what() +
                     " (lavapipe comes with Debian's mesa-vulkan-drivers; see scripts/setup.sh)");
  }
}

std::array<int, 2> parseSize(const std::string& text, const std::string& option) {
  const size_t x = text.find_first_of("xX");
  if (x == std::string::npos) throw InputError(option + ": '" + text + "' is not WIDTHxHEIGHT, e.g. 1280x720");
  return {parseCount(text.substr(0, x), option, 1, 16384), parseCount(text.substr(x + 1), option, 1, 16384)};
}

std::array<float, 4> parseBackground(const std::string& text, const std::string& option) {
  if (text == "transparent") return {0, 0, 0, 0};
  const std::string hex = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  if ((hex.size() != 6 && hex.size() != 8) ||
      !std::all_of(hex.begin(), hex.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); }))
    throw InputError(option + ": '" + text + "' is not 'transparent' or a colour RRGGBB or RRGGBBAA");
  std::array<float, 4> colour{0, 0, 0, 1};
  for (size_t c = 0; c < hex.size() / 2; ++c) colour[c] = std::strtol(hex.substr(2 * c, 2).c_str(), nullptr, 16) / 255.0f;
  return colour;
}

std::optional<render::Sampling> parseSampling(const cli::Arguments& a, const std::string& option) {
  if (!a.has("sampling")) return std::nullopt;
  const std::string sampling = a.value("sampling", "");
  if (sampling == "linear") return render::Sampling::kLinear;
  if (sampling == "nearest") return render::Sampling::kNearest;
  throw InputError(option + ": '" + sampling + "' is not linear or nearest");
}

RenderOptions parseRenderOptions(const cli::Arguments& a) {
  RenderOptions o;
  if (!a.has("output")) throw InputError("render: needs -o DIR, the folder for the frames");
  o.output = a.value("output", "");
  if (a.has("frames")) o.frames = cli::frameRange(a.value("frames", ""), "--frames");
  if (a.has("size")) o.size = parseSize(a.value("size", ""), "--size");
  try {
    o.canvas = render::parseCanvas(a.value("canvas", "drawing"));
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--canvas: ") + e.what());
  }
  o.target.samples = a.integer("samples", 4, 1, 64);
  o.target.background = parseBackground(a.value("background", "transparent"), "--background");
  o.overlays.wireframe = a.flag("wireframe");
  o.overlays.cohesive = a.flag("cohesive");
  o.overlays.features = a.flag("features");
  o.onion = a.integer("onion", 0, 0, render::kMaxOnionSkins / 2);
  o.sheetEvery = a.integer("sheet-every", 0, 0, 100000);
  if (a.has("sheet-frames")) {
    if (a.has("sheet-every")) throw InputError("render: --sheet-frames and --sheet-every both choose the sheet's frames: give one");
    o.sheetFrames = cli::integerList(a.value("sheet-frames", ""), "sheet-frames", 0, 100000000);
    std::sort(o.sheetFrames.begin(), o.sheetFrames.end());
    o.sheetFrames.erase(std::unique(o.sheetFrames.begin(), o.sheetFrames.end()), o.sheetFrames.end());
  }
  o.sheetColumns = a.integer("sheet-columns", 0, 0, 1000);
  o.preview = a.flag("preview");
  o.mesh.meshFile = a.value("mesh", "");
  o.mesh.comesh = !a.flag("no-comesh");
  const std::string device = a.value("device", "any");
  if (device == "any") o.device = vk::DevicePreference::kAny;
  else if (device == "gpu") o.device = vk::DevicePreference::kHardware;
  else if (device == "cpu") o.device = vk::DevicePreference::kSoftware;
  else throw InputError("--device: '" + device + "' is not any, gpu or cpu");
  o.validation = a.flag("validation");
  o.threads = a.integer("threads", 0, 0, cli::kMaxThreads);
  return o;
}

}  // namespace ib
