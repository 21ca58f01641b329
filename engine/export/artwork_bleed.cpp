#include "export/artwork_bleed.h"

#include <array>
#include <vector>

namespace ib::gltf {

RgbaImage bleedColour(const RgbaImage& image, int passes) {
  RgbaImage out = image;
  const int w = image.width, h = image.height;
  std::vector<char> known(static_cast<size_t>(w) * h);
  std::array<double, 3> sum{0, 0, 0};
  size_t drawn = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = image.at(x, y);
      known[static_cast<size_t>(y) * w + x] = p[3] > 0;
      if (p[3] == 0) continue;
      for (int c = 0; c < 3; ++c) sum[c] += p[c];
      ++drawn;
    }
  if (drawn == 0) return out;
  std::vector<size_t> ring;
  for (int pass = 0; pass < passes; ++pass) {
    ring.clear();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (known[static_cast<size_t>(y) * w + x]) continue;
        std::array<int, 3> acc{0, 0, 0};
        int count = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h || !known[static_cast<size_t>(ny) * w + nx]) continue;
            const uint8_t* q = out.at(nx, ny);
            for (int c = 0; c < 3; ++c) acc[c] += q[c];
            ++count;
          }
        if (count == 0) continue;
        uint8_t* p = out.at(x, y);
        for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>((acc[c] + count / 2) / count);
        ring.push_back(static_cast<size_t>(y) * w + x);
      }
    if (ring.empty()) break;
    for (size_t i : ring) known[i] = 1;
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (known[static_cast<size_t>(y) * w + x]) continue;
      uint8_t* p = out.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>(sum[c] / drawn + 0.5);
    }
  out.hasAlpha = true;
  return out;
}

}  // namespace ib::gltf
