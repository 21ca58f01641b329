// The renderer's graphics pipelines for one render pass and sample count:
// - artwork: triangle list, vertex binding 0 = ArtworkVertex (vec2 position + float seam closure,
//   12 bytes), descriptor set 0 =
//   {0: the artwork's sampler2DArray, 1: the per-key UVs storage buffer}, push constants ArtworkPush;
// - overlay lines and overlay triangles: vertex binding 0 = vec2 position + vec4 premultiplied colour
//   (24 bytes), push constants {vec4 view}.
// - the drawing sheet (the editor's keys): no vertex input, descriptor set 0 = {0: the artwork's
//   sampler2DArray}, push constants SheetPush.
// All blend premultiplied colour over the target (ONE, ONE_MINUS_SRC_ALPHA), without culling or
// depth, with dynamic viewport and scissor; the artwork pipelines use the stencil (render_pass.h).
#pragma once

#include "gpu/vulkan_object.h"

#include <array>

namespace ib::vk {

// Matches the push_constant block in shaders/artwork_push.glsl (std430, 112 bytes).
struct ArtworkPush {
  float view[4];     // clip = position * view.xy + view.zw
  float tint[4];     // multiplies the premultiplied colour
  float weights[8];  // active keys' weights
  int layers[8];     // active keys' texture layers (= key indices)
  int activeCount;   // 0..8
  int keyCount;      // m
  float keyness;     // 0..1: how much the keys' own drawings (layers m..2m-1) show (render::keyness)
  int rim;           // 1 while drawing the keys' rims (render::KeyRim), 0 for the mesh
};
static_assert(sizeof(ArtworkPush) == 112, "ArtworkPush must match shaders/artwork_push.glsl");

struct ArtworkVertex {
  float position[2];  // drawing pixels
  float seamClosure;  // 0..1, see render::weldCuts
  // The outline ink drawn along an opened cut (render::inkFrame): distance to the cut's side and
  // the line's width (target pixels), how much of it (0..1), its colour (straight RGB).
  float inkDistance, inkWidth, inkAlpha;
  float inkColour[3];
};

struct OverlayVertex {
  float position[2];  // drawing pixels
  float colour[4];    // premultiplied RGBA
};

struct RendererPipelines {
  DescriptorSetLayoutObject setLayout;
  PipelineLayoutObject artworkLayout;
  PipelineLayoutObject overlayLayout;
  // For up to 2, 4 and 8 active keys: the mesh (writes the draw's stencil reference, dynamic), and
  // the keys' rims (render::KeyRim: only where the stencil is not yet the reference, writing it).
  std::array<PipelineObject, 3> artwork;
  std::array<PipelineObject, 3> rim;
  PipelineObject overlayLines;
  PipelineObject overlayTriangles;
};

// Index into RendererPipelines::artwork of the cheapest variant that draws `activeKeys` keys (1..8).
int artworkVariant(int activeKeys);

RendererPipelines createRendererPipelines(VkDevice device, VkRenderPass pass, VkSampleCountFlagBits samples);

// Matches the push_constant block in shaders/sheet_push.glsl (std430, 64 bytes).
struct SheetPush {
  float clipRect[4];  // x0, y0, x1, y1 in clip space
  float uvRect[4];    // u0, v0, u1, v1 of the layer
  float colour[4];    // premultiplied tint, or the fill for layer < 0
  int layer;          // artwork layer, -1: a plain fill
  int padding[3];
};
static_assert(sizeof(SheetPush) == 64, "SheetPush must match shaders/sheet_push.glsl");

struct SheetPipeline {
  DescriptorSetLayoutObject setLayout;
  PipelineLayoutObject layout;
  PipelineObject pipeline;
};

SheetPipeline createSheetPipeline(VkDevice device, VkRenderPass pass, VkSampleCountFlagBits samples);

}  // namespace ib::vk
