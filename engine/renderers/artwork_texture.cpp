#include "renderers/artwork_texture.h"

#include "gpu/vulkan_check.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace ib::vk {

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

}  // namespace

ArtworkTexture uploadArtwork(const VulkanContext& context, VkCommandPool pool, const render::TextureLevels& levels) {
  ArtworkTexture out;
  const render::TextureLevels::Level& base = levels.levels.at(0);
  out.layerSize = {static_cast<uint32_t>(base.width), static_cast<uint32_t>(base.height)};
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
  if (out.layerSize.width > properties.limits.maxImageDimension2D || out.layerSize.height > properties.limits.maxImageDimension2D ||
      static_cast<uint32_t>(levels.layers) > properties.limits.maxImageArrayLayers)
    throw VulkanError("the drawings (" + std::to_string(out.layerSize.width) + "x" + std::to_string(out.layerSize.height) +
                          " px, " + std::to_string(levels.layers) + " keys) exceed the device's texture limits (" +
                          std::to_string(properties.limits.maxImageDimension2D) + " px)",
                      VK_ERROR_FORMAT_NOT_SUPPORTED);
  GpuBuffer staging = createBuffer(context, levels.texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true,
                                   "the artwork staging buffer");
  std::memcpy(staging.mapped, levels.texels.data(), levels.texels.size());
  ImageSpec spec;
  spec.extent = out.layerSize;
  spec.layers = static_cast<uint32_t>(levels.layers);
  spec.arrayView = true;  // the shader samples a sampler2DArray, also for one key
  spec.mipLevels = static_cast<uint32_t>(levels.levels.size());
  spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  out.image = createImage(context, spec, "the artwork texture");
  std::vector<VkBufferImageCopy> regions;
  for (size_t l = 0; l < levels.levels.size(); ++l) {
    VkBufferImageCopy region{};
    region.bufferOffset = levels.levels[l].offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<uint32_t>(l), 0, spec.layers};
    region.imageExtent = {static_cast<uint32_t>(levels.levels[l].width), static_cast<uint32_t>(levels.levels[l].height), 1};
    regions.push_back(region);
  }
  const VkBuffer source = staging.buffer.get();  // `staging` itself goes into the Submission
  out.upload = submit(context, pool, [&](VkCommandBuffer cmd) {
    transitionImage(cmd, out.image.image.get(), spec.layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, 0,
                    spec.mipLevels);
    vkCmdCopyBufferToImage(cmd, source, out.image.image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           static_cast<uint32_t>(regions.size()), regions.data());
    transitionImage(cmd, out.image.image.get(), spec.layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT, 0, spec.mipLevels);
  }, std::move(staging));
  out.linear = createSampler(context.device(), false);
  out.nearest = createSampler(context.device(), true);
  return out;
}

ArtworkTexture uploadArtwork(const VulkanContext& context, VkCommandPool pool, const std::vector<RgbaImage>& drawings) {
  return uploadArtwork(context, pool, render::textureLevels(drawings));
}

}  // namespace ib::vk
