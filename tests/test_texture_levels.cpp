// The artwork's mip chain made on the CPU (output/texture_levels.h), so that the player prepares it
// off its window's thread: sizes, padding and premultiplication, and agreement with the linear
// blits the device would make (Mesa's lavapipe here), level by level.
#include "gpu/gpu_resources.h"
#include "gpu/vulkan_check.h"
#include "output/texture_levels.h"
#include "render_fixtures.h"
#include "vulkan_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>

using namespace ib;
using namespace ib::render;

namespace {

using Colour = std::array<uint8_t, 4>;

// A drawing with detail at every scale: stripes, a gradient and partly transparent texels.
RgbaImage detailed(int width, int height) {
  return test::paintedImage(width, height, [](int x, int y) {
    return Colour{static_cast<uint8_t>((x * 37 + y * 11) % 256), static_cast<uint8_t>(x % 3 == 0 ? 255 : 20),
                  static_cast<uint8_t>(y * 5 % 256), static_cast<uint8_t>((x + y) % 7 == 0 ? 0 : 255 - (x * y) % 128)};
  });
}

// Level 0 uploaded, every next level blitted from the one before with VK_FILTER_LINEAR, all read
// back: the chain the device makes, in TextureLevels' layout.
std::vector<uint8_t> deviceChain(const vk::VulkanContext& context, const TextureLevels& cpu) {
  const vk::CommandPoolObject pool = vk::createCommandPool(context);
  const uint32_t layers = static_cast<uint32_t>(cpu.layers), levels = static_cast<uint32_t>(cpu.levels.size());
  vk::GpuBuffer buffer = vk::createBuffer(context, cpu.texels.size(),
                                          VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, true, "the test buffer");
  std::memset(buffer.mapped, 0, cpu.texels.size());
  std::memcpy(buffer.mapped, cpu.texels.data(), static_cast<size_t>(cpu.levels[0].width) * cpu.levels[0].height * 4 * layers);
  vk::ImageSpec spec;
  spec.extent = {static_cast<uint32_t>(cpu.levels[0].width), static_cast<uint32_t>(cpu.levels[0].height)};
  spec.layers = layers;
  spec.arrayView = true;
  spec.mipLevels = levels;
  spec.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  const vk::GpuImage image = vk::createImage(context, spec, "the test image");
  VkImage handle = image.image.get();
  vk::submitAndWait(context, pool.get(), [&](VkCommandBuffer cmd) {
    vk::transitionImage(cmd, handle, layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, 0, levels);
    VkBufferImageCopy base{};
    base.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
    base.imageExtent = {spec.extent.width, spec.extent.height, 1};
    vkCmdCopyBufferToImage(cmd, buffer.buffer.get(), handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &base);
    for (uint32_t l = 1; l < levels; ++l) {
      vk::transitionImage(cmd, handle, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_READ_BIT, l - 1, 1);
      VkImageBlit blit{};
      blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l - 1, 0, layers};
      blit.srcOffsets[1] = {cpu.levels[l - 1].width, cpu.levels[l - 1].height, 1};
      blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, layers};
      blit.dstOffsets[1] = {cpu.levels[l].width, cpu.levels[l].height, 1};
      vkCmdBlitImage(cmd, handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                     VK_FILTER_LINEAR);
    }
    vk::transitionImage(cmd, handle, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                        VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_TRANSFER_READ_BIT, levels - 1, 1);
    std::vector<VkBufferImageCopy> regions;
    for (uint32_t l = 0; l < levels; ++l) {
      VkBufferImageCopy region{};
      region.bufferOffset = cpu.levels[l].offset;
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, layers};
      region.imageExtent = {static_cast<uint32_t>(cpu.levels[l].width), static_cast<uint32_t>(cpu.levels[l].height), 1};
      regions.push_back(region);
    }
    vkCmdCopyImageToBuffer(cmd, handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer.get(), levels, regions.data());
  });
  const auto* bytes = static_cast<const uint8_t*>(buffer.mapped);
  return std::vector<uint8_t>(bytes, bytes + cpu.texels.size());
}

}  // namespace

TEST_CASE("texture levels: each level halves the one above down to 1 x 1, layers padded transparent, texels premultiplied") {
  const TextureLevels t = textureLevels({detailed(37, 20), detailed(12, 30)});
  REQUIRE(t.layers == 2);
  REQUIRE(t.levels.front().width == 37);
  REQUIRE(t.levels.front().height == 30);
  REQUIRE(t.levels.size() == 6);  // 37x30, 18x15, 9x7, 4x3, 2x1, 1x1
  CHECK(t.levels.back().width == 1);
  CHECK(t.levels.back().height == 1);
  const RgbaImage drawing = detailed(37, 20);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 37; ++x) {
      const uint8_t* texel = t.texels.data() + 4 * (static_cast<size_t>(y) * 37 + x);
      if (y >= 20) {
        CHECK(texel[3] == 0);  // padding below the shorter drawing
        continue;
      }
      const uint8_t* straight = drawing.at(x, y);
      CHECK(texel[3] == straight[3]);
      for (int c = 0; c < 3; ++c) CHECK(std::abs(texel[c] - straight[c] * straight[3] / 255.0) <= 0.5);
    }
  CHECK_THROWS_AS(textureLevels({}), std::invalid_argument);
}

TEST_CASE("texture levels: every level is what the device's linear blit makes of the level above, within 1/255") {
  const vk::VulkanContext context = test::validatedContext();
  // Even sides (exact 2 x 2 averages), odd ones (bilinear taps), and a strip (one side clamps at 1).
  // Opaque drawings of one size (no padding), so that a level read back from the device is a
  // drawing whose next level textureLevels makes as it makes any (premultiplying is the identity).
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{64, 32}, {37, 23}, {5, 40}}) {
    INFO(w << " x " << h);
    const auto opaque = [](RgbaImage image) {
      for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
      return image;
    };
    RgbaImage second = detailed(w, h);
    std::reverse(second.pixels.begin(), second.pixels.end());
    const TextureLevels cpu = textureLevels({opaque(detailed(w, h)), opaque(second)});
    const std::vector<uint8_t> device = deviceChain(context, cpu);
    for (size_t l = 1; l < cpu.levels.size(); ++l)
      for (int layer = 0; layer < cpu.layers; ++layer) {
        INFO("level " << l << ", layer " << layer);
        const TextureLevels::Level& above = cpu.levels[l - 1];
        const TextureLevels::Level& level = cpu.levels[l];
        RgbaImage read;  // the device's level above
        read.width = above.width;
        read.height = above.height;
        const size_t from = above.offset + static_cast<size_t>(above.width) * above.height * 4 * layer;
        read.pixels.assign(device.begin() + static_cast<std::ptrdiff_t>(from),
                           device.begin() + static_cast<std::ptrdiff_t>(from + static_cast<size_t>(above.width) * above.height * 4));
        const TextureLevels next = textureLevels({read});
        REQUIRE(next.levels[1].width == level.width);
        REQUIRE(next.levels[1].height == level.height);
        const size_t at = level.offset + static_cast<size_t>(level.width) * level.height * 4 * layer;
        int largest = 0;
        for (size_t i = 0; i < static_cast<size_t>(level.width) * level.height * 4; ++i)
          largest = std::max(largest, std::abs(int(next.texels[next.levels[1].offset + i]) - int(device[at + i])));
        CHECK(largest <= 1);
      }
  }
}
