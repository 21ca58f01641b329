#include "output/key_fidelity.h"

#include "output/texture_levels.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace ib::render {

RgbaImage magnifiedDrawing(const RgbaImage& drawing, int scale, bool nearest) {
  if (scale < 1) throw std::invalid_argument("keyFidelity: the scale must be at least 1");
  const RgbaImage texels = premultiplied(drawing);
  RgbaImage out;
  out.width = drawing.width * scale;
  out.height = drawing.height * scale;
  out.pixels.assign(4 * static_cast<size_t>(out.width) * out.height, 0);
  auto texel = [&](int x, int y, int c) {
    x = std::clamp(x, 0, texels.width - 1);
    y = std::clamp(y, 0, texels.height - 1);
    return static_cast<double>(texels.at(x, y)[c]);
  };
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      uint8_t* o = &out.pixels[4 * (static_cast<size_t>(y) * out.width + x)];
      if (nearest) {
        for (int c = 0; c < 4; ++c) o[c] = texels.at(x / scale, y / scale)[c];
        continue;
      }
      // The target pixel's centre in texel units, less the texel centre's half.
      const double u = (x + 0.5) / scale - 0.5, v = (y + 0.5) / scale - 0.5;
      const int x0 = static_cast<int>(std::floor(u)), y0 = static_cast<int>(std::floor(v));
      const double fx = u - x0, fy = v - y0;
      for (int c = 0; c < 4; ++c) {
        const double value = (1 - fy) * ((1 - fx) * texel(x0, y0, c) + fx * texel(x0 + 1, y0, c)) +
                             fy * ((1 - fx) * texel(x0, y0 + 1, c) + fx * texel(x0 + 1, y0 + 1, c));
        o[c] = static_cast<uint8_t>(std::lround(std::clamp(value, 0.0, 255.0)));
      }
    }
  return out;
}

KeyFidelity keyFidelity(const RgbaImage& frame, const RgbaImage& drawing, int scale, bool nearest, int tolerance) {
  const RgbaImage want = magnifiedDrawing(drawing, scale, nearest);
  const RgbaImage got = premultiplied(frame);
  KeyFidelity f;
  const int width = std::max(want.width, got.width), height = std::max(want.height, got.height);
  static const uint8_t kNone[4] = {0, 0, 0, 0};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* a = x < want.width && y < want.height ? want.at(x, y) : kNone;
      const uint8_t* b = x < got.width && y < got.height ? got.at(x, y) : kNone;
      int d = 0;
      for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
      ++f.pixels;
      f.over += d > tolerance;
      if (d > f.worst) f.worst = d, f.worstX = x, f.worstY = y;
    }
  return f;
}

}  // namespace ib::render
