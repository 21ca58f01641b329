#include "pipeline/artwork_sampling.h"

#include "scene/scene.h"

#include <cstdint>
#include <unordered_set>

namespace ib {

bool isPixelArt(const std::vector<RgbaImage>& drawings) {
  if (drawings.empty()) return false;
  std::unordered_set<uint32_t> colours;
  for (const RgbaImage& d : drawings) {
    const size_t n = static_cast<size_t>(d.width) * static_cast<size_t>(d.height);
    for (size_t i = 0; i < n && 4 * i + 3 < d.pixels.size(); ++i) {
      const uint8_t* p = d.pixels.data() + 4 * i;
      if (p[3] == 0) continue;
      if (p[3] != 255) return false;  // an antialiased (or soft) edge
      colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
      if (static_cast<int>(colours.size()) > kPixelArtColours) return false;
    }
  }
  return true;
}

bool nearestSampling(const Scene& scene, const std::vector<RgbaImage>& drawings) {
  switch (scene.sampling) {
    case ArtworkSampling::kNearest: return true;
    case ArtworkSampling::kLinear: return false;
    case ArtworkSampling::kAuto: return isPixelArt(drawings);
  }
  return false;
}

}  // namespace ib
