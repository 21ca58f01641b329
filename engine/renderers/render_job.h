// `inbetween render`'s work as a job: a scene's frames solved in order (pipeline/scene_frames.h)
// and drawn headless, two frames in flight, each written as a PNG as it comes back; then the
// contact sheet and, if asked, the animated preview. It reports progress and leaves the command
// line to the front end.
#pragma once

#include "core/png_image.h"
#include "output/canvas.h"
#include "pipeline/scene_frames.h"
#include "renderers/offscreen_renderer.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace ib::vk {
class VulkanContext;
}

namespace ib::render {

struct RenderJobOptions {
  std::string folder;                  // where the files go (it exists); frame_NNNN.png, contact_sheet.png, preview.png
  std::array<int, 2> frames{0, 0};     // first and last frame, inclusive, within the timeline
  OffscreenOptions target;             // size (width, height; 0 x 0: the canvas at 1:1), samples, background
  CanvasChoice canvas;                 // what part of the drawing plane the frames show (default the drawings' canvas)
  Overlays overlays;                   // wireframe, cohesive edges, features
  Sampling sampling = Sampling::kLinear;
  int onion = 0;                       // neighbouring frames drawn each side as onion skins, 0..2
  int sheetEvery = 0;                  // every k-th frame on the contact sheet; 0: at most 36 tiles
  std::vector<int> sheetFrames;        // just these frames on the sheet, ascending; empty: by sheetEvery
  int sheetColumns = 0;                // tiles per row; 0: about square
  bool preview = false;                // also preview.png: every frame at tile size, an animated PNG
  FrameOptions solving;                // how the frames are solved (threads, ...)
};

struct RenderJobReport {
  int written = 0;                     // frames written
  double seconds = 0;                  // wall time of solving and drawing them
  std::string firstFrame, lastFrame;   // their paths
  std::string sheet, preview;          // paths; preview empty when not asked
  int width = 0, height = 0;           // the frames' size, px
  ViewBox canvas;                      // the part of the drawing plane they show, drawing px
  CanvasReach reach;                   // the frames that reach past it
};

// stage: what is being done, e.g. "rendering frame 12 (13 of 48)"; fraction of the job in [0, 1].
using JobProgress = std::function<void(const std::string& stage, double fraction)>;

// The path of frame `frame` in `folder`: folder/frame_NNNN.png.
std::string framePath(const std::string& folder, int frame);

// Renders `scene`'s frames on `mesh` (a multimesh of the scene) with the key drawings of the
// scene (pipeline/key_drawings.h) and its feature vertices (for the overlays). With a fitted
// canvas the frames are solved twice: once for the animation's bounds, then to draw. InputError for a
// frame range outside the timeline, sheet frames outside it, or a size the device has no memory
// for (naming the option and what to do); vk::VulkanError for a device failure.
RenderJobReport renderFrames(const vk::VulkanContext& context, const Scene& scene, const Multimesh& mesh,
                             std::vector<RgbaImage> drawings, const std::vector<int>& features,
                             const RenderJobOptions& options, const JobProgress& progress = nullptr);

}  // namespace ib::render
