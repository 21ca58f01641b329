// Every key's drawing in one 2D-array texture, one layer per key, premultiplied alpha, RGBA8
// UNORM (blending happens in the drawings' own colour values, as in 2D paint programs). Layers
// share the largest drawing's size; a smaller drawing sits in its layer's top-left corner with
// transparent padding, so its UVs scale by drawing size / layer size. A full mip chain (made on the
// CPU as linear blits would make it: output/texture_levels.h) and trilinear filtering keep line art
// smooth when drawn smaller; a second, nearest-neighbour sampler keeps magnified pixel art crisp
// (render::Sampling).
#pragma once

#include "core/png_image.h"
#include "gpu/gpu_resources.h"
#include "output/texture_levels.h"

#include <utility>
#include <vector>

namespace ib::vk {

struct ArtworkTexture {
  ArtworkTexture() = default;
  ArtworkTexture(ArtworkTexture&&) noexcept = default;
  // Waits for this texture's copy before its image goes (the implicit one would replace the
  // image first).
  ArtworkTexture& operator=(ArtworkTexture&& other) noexcept {
    upload = std::move(other.upload);
    image = std::move(other.image);
    linear = std::move(other.linear);
    nearest = std::move(other.nearest);
    layerSize = other.layerSize;
    return *this;
  }

  GpuImage image;           // layers = keys, every mip level in VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
  SamplerObject linear;     // trilinear, clamped to the edge
  SamplerObject nearest;    // nearest texel of the nearest mip level, clamped to the edge
  VkExtent2D layerSize{};   // pixels
  Submission upload;        // the copy into `image`, on the queue (keeps its staging buffer until done);
                            // last, so that it is destroyed (waited for) first
};

// The copy is submitted, not waited for: draws submitted after it to the same queue sample the
// finished texture. Throws VulkanError when the device cannot hold it (e.g. a layer above
// maxImageDimension2D).
ArtworkTexture uploadArtwork(const VulkanContext& context, VkCommandPool pool, const render::TextureLevels& levels);
// The same from the drawings (straight alpha): render::textureLevels of them, then uploaded.
ArtworkTexture uploadArtwork(const VulkanContext& context, VkCommandPool pool, const std::vector<RgbaImage>& drawings);

}  // namespace ib::vk
