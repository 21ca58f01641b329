#include "output/texture_levels.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

namespace ib::render {

RgbaImage premultiplied(const RgbaImage& image) {
  RgbaImage out = image;
  for (size_t p = 0; p + 3 < out.pixels.size(); p += 4) {
    const unsigned a = out.pixels[p + 3];
    for (int c = 0; c < 3; ++c) out.pixels[p + c] = static_cast<uint8_t>((out.pixels[p + c] * a + 127) / 255);
  }
  return out;
}

namespace {

// One side's bilinear taps for a blit from `from` texels to `to`: destination texel i samples the
// source at (i + 0.5) * from / to, between texels first[i] and first[i] + 1 (clamped) with weight
// w[i] on the second.
struct Taps {
  std::vector<int> first, second;
  std::vector<float> w;
};

Taps taps(int from, int to) {
  Taps t;
  for (int i = 0; i < to; ++i) {
    const double u = (i + 0.5) * from / to - 0.5;
    const int i0 = static_cast<int>(std::floor(u));
    t.first.push_back(std::clamp(i0, 0, from - 1));
    t.second.push_back(std::clamp(i0 + 1, 0, from - 1));
    t.w.push_back(static_cast<float>(u - i0));
  }
  return t;
}

// Level `to` of one layer from level `from` (RGBA8, rows of width * 4 bytes).
void downsample(const uint8_t* from, int fw, int fh, uint8_t* to, int tw, int th) {
  if (fw == 2 * tw && fh == 2 * th) {  // the exact 2 x 2 average, rounded
    for (int y = 0; y < th; ++y)
      for (int x = 0; x < tw; ++x) {
        const uint8_t* a = from + 4 * (static_cast<size_t>(2 * y) * fw + 2 * x);
        const uint8_t* b = a + 4 * static_cast<size_t>(fw);
        uint8_t* o = to + 4 * (static_cast<size_t>(y) * tw + x);
        for (int c = 0; c < 4; ++c) o[c] = static_cast<uint8_t>((a[c] + a[c + 4] + b[c] + b[c + 4] + 2) / 4);
      }
    return;
  }
  const Taps tx = taps(fw, tw), ty = taps(fh, th);
  for (int y = 0; y < th; ++y) {
    const uint8_t* r0 = from + 4 * static_cast<size_t>(ty.first[y]) * fw;
    const uint8_t* r1 = from + 4 * static_cast<size_t>(ty.second[y]) * fw;
    const float wy = ty.w[y];
    for (int x = 0; x < tw; ++x) {
      const int x0 = 4 * tx.first[x], x1 = 4 * tx.second[x];
      const float wx = tx.w[x];
      uint8_t* o = to + 4 * (static_cast<size_t>(y) * tw + x);
      for (int c = 0; c < 4; ++c) {
        const float top = (1 - wx) * r0[x0 + c] + wx * r0[x1 + c];
        const float bottom = (1 - wx) * r1[x0 + c] + wx * r1[x1 + c];
        o[c] = static_cast<uint8_t>(std::lround(std::clamp((1 - wy) * top + wy * bottom, 0.0f, 255.0f)));
      }
    }
  }
}

}  // namespace

TextureLevels textureLevels(const std::vector<RgbaImage>& drawings) {
  if (drawings.empty()) throw std::invalid_argument("texture: no drawings");
  TextureLevels out;
  out.layers = static_cast<int>(drawings.size());
  int width = 0, height = 0;
  for (size_t k = 0; k < drawings.size(); ++k) {
    if (drawings[k].width <= 0 || drawings[k].height <= 0)
      throw std::invalid_argument("texture: the drawing of key " + std::to_string(k) + " is empty");
    width = std::max(width, drawings[k].width);
    height = std::max(height, drawings[k].height);
  }
  size_t bytes = 0;
  for (int w = width, h = height;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
    out.levels.push_back({w, h, bytes});
    bytes += static_cast<size_t>(w) * h * 4 * out.layers;
    if (w == 1 && h == 1) break;
  }
  out.texels.assign(bytes, 0);
  // Every layer on its own, in parallel: each writes only its own texels. An exception (out of
  // memory) is rethrown here.
  std::exception_ptr failed;
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < out.layers; ++k) try {
    const RgbaImage& d = drawings[static_cast<size_t>(k)];
    const size_t layer0 = static_cast<size_t>(width) * height * 4 * k;
    for (int y = 0; y < d.height; ++y) {
      uint8_t* row = out.texels.data() + layer0 + static_cast<size_t>(y) * width * 4;
      const uint8_t* in = d.at(0, y);
      for (int x = 0; x < d.width; ++x) {
        const unsigned a = in[4 * x + 3];
        for (int c = 0; c < 3; ++c) row[4 * x + c] = static_cast<uint8_t>((in[4 * x + c] * a + 127) / 255);
        row[4 * x + 3] = static_cast<uint8_t>(a);
      }
    }
    for (size_t l = 1; l < out.levels.size(); ++l) {
      const TextureLevels::Level& a = out.levels[l - 1];
      const TextureLevels::Level& b = out.levels[l];
      downsample(out.texels.data() + a.offset + static_cast<size_t>(a.width) * a.height * 4 * k, a.width, a.height,
                 out.texels.data() + b.offset + static_cast<size_t>(b.width) * b.height * 4 * k, b.width, b.height);
    }
  } catch (...) {
#pragma omp critical(texture_levels_failed)
    if (!failed) failed = std::current_exception();
  }
  if (failed) std::rethrow_exception(failed);
  return out;
}

}  // namespace ib::render
