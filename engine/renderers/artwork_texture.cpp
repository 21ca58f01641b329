#include "renderers/artwork_texture.h"

#include "gpu/vulkan_check.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace ib::vk {

RgbaImage premultiplied(const RgbaImage& image) {
  RgbaImage out = image;
  for (size_t p = 0; p + 3 < out.pixels.size(); p += 4) {
    const unsigned a = out.pixels[p + 3];
    for (int c = 0; c < 3; ++c) out.pixels[p + c] = static_cast<uint8_t>((out.pixels[p + c] * a + 127) / 255);
  }
  return out;
}

namespace {

// Trilinear (`nearest` false): shrunk line art neither shimmers nor pops between levels. Nearest:
// texels and mip levels alike, so no two texels are ever mixed and magnified pixel edges stay hard.
SamplerObject createSampler(VkDevice device, bool nearest) {
  VkSamplerCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  info.magFilter = info.minFilter = nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
  info.mipmapMode = nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = VK_LOD_CLAMP_NONE;
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(device, &info, nullptr, &sampler),
        nearest ? "creating the nearest-neighbour artwork sampler" : "creating the trilinear artwork sampler");
  return SamplerObject(device, sampler);
}

// A full mip chain when the device can blit RGBA8 with linear filtering, else one level.
uint32_t mipLevelCount(const VulkanContext& context, VkExtent2D size) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), VK_FORMAT_R8G8B8A8_UNORM, &properties);
  const VkFormatFeatureFlags needed =
      VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((properties.optimalTilingFeatures & needed) != needed) return 1;
  uint32_t levels = 1;
  for (uint32_t side = std::max(size.width, size.height); side > 1; side /= 2) ++levels;
  return levels;
}

// Level 0 (in TRANSFER_DST) halved into each next level by linear blits, then every level made
// shader-readable. Premultiplied texels average correctly.
void recordMipChain(VkCommandBuffer cmd, VkImage image, VkExtent2D size, uint32_t layers, uint32_t levels) {
  int32_t w = static_cast<int32_t>(size.width), h = static_cast<int32_t>(size.height);
  for (uint32_t level = 1; level < levels; ++level) {
    transitionImage(cmd, image, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT, level - 1, 1);
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, layers};
    blit.srcOffsets[1] = {w, h, 1};
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layers};
    blit.dstOffsets[1] = {w, h, 1};
    vkCmdBlitImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                   VK_FILTER_LINEAR);
    transitionImage(cmd, image, layers, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_SHADER_READ_BIT, level - 1, 1);
  }
  transitionImage(cmd, image, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT, levels - 1, 1);
}

}  // namespace

ArtworkTexture uploadArtwork(const VulkanContext& context, VkCommandPool pool, const std::vector<RgbaImage>& drawings) {
  ArtworkTexture out;
  for (const RgbaImage& d : drawings) {
    out.layerSize.width = std::max(out.layerSize.width, static_cast<uint32_t>(d.width));
    out.layerSize.height = std::max(out.layerSize.height, static_cast<uint32_t>(d.height));
  }
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
  if (out.layerSize.width > properties.limits.maxImageDimension2D || out.layerSize.height > properties.limits.maxImageDimension2D ||
      drawings.size() > properties.limits.maxImageArrayLayers)
    throw VulkanError("the drawings (" + std::to_string(out.layerSize.width) + "x" + std::to_string(out.layerSize.height) +
                          " px, " + std::to_string(drawings.size()) + " keys) exceed the device's texture limits (" +
                          std::to_string(properties.limits.maxImageDimension2D) + " px)",
                      VK_ERROR_FORMAT_NOT_SUPPORTED);
  const size_t layerBytes = static_cast<size_t>(out.layerSize.width) * out.layerSize.height * 4;
  GpuBuffer staging = createBuffer(context, layerBytes * drawings.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true,
                                   "the artwork staging buffer");
  auto* bytes = static_cast<uint8_t*>(staging.mapped);
  std::memset(bytes, 0, staging.size);
  for (size_t k = 0; k < drawings.size(); ++k) {
    const RgbaImage layer = premultiplied(drawings[k]);
    for (int y = 0; y < layer.height; ++y)
      std::memcpy(bytes + k * layerBytes + static_cast<size_t>(y) * out.layerSize.width * 4, layer.at(0, y),
                  static_cast<size_t>(layer.width) * 4);
  }
  ImageSpec spec;
  spec.extent = out.layerSize;
  spec.layers = static_cast<uint32_t>(drawings.size());
  spec.arrayView = true;  // the shader samples a sampler2DArray, also for one key
  spec.mipLevels = mipLevelCount(context, out.layerSize);
  spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  out.image = createImage(context, spec, "the artwork texture");
  submitAndWait(context, pool, [&](VkCommandBuffer cmd) {
    transitionImage(cmd, out.image.image.get(), spec.layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, 0,
                    spec.mipLevels);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, spec.layers};
    region.imageExtent = {out.layerSize.width, out.layerSize.height, 1};
    vkCmdCopyBufferToImage(cmd, staging.buffer.get(), out.image.image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    recordMipChain(cmd, out.image.image.get(), out.layerSize, spec.layers, spec.mipLevels);
  });
  out.linear = createSampler(context.device(), false);
  out.nearest = createSampler(context.device(), true);
  return out;
}

}  // namespace ib::vk
