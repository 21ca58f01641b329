#include "output/contact_sheet.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace ib::render {

RgbaImage shrink(const RgbaImage& frame, int width, int height) {
  width = std::clamp(width, 1, frame.width);
  height = std::clamp(height, 1, frame.height);
  RgbaImage out;
  out.width = width;
  out.height = height;
  out.hasAlpha = frame.hasAlpha;
  out.pixels.resize(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    const int y0 = y * frame.height / height, y1 = std::max(y0 + 1, (y + 1) * frame.height / height);
    for (int x = 0; x < width; ++x) {
      const int x0 = x * frame.width / width, x1 = std::max(x0 + 1, (x + 1) * frame.width / width);
      double sum[4] = {0, 0, 0, 0};
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx) {
          const uint8_t* p = frame.at(sx, sy);
          const double a = p[3] / 255.0;
          for (int c = 0; c < 3; ++c) sum[c] += p[c] * a;
          sum[3] += p[3];
        }
      const double count = static_cast<double>(x1 - x0) * (y1 - y0);
      uint8_t* q = out.at(x, y);
      const double alpha = sum[3] / count;
      for (int c = 0; c < 3; ++c) q[c] = alpha > 0 ? static_cast<uint8_t>(std::lround(std::min(255.0, sum[c] / count * 255.0 / alpha))) : 0;
      q[3] = static_cast<uint8_t>(std::lround(alpha));
    }
  }
  return out;
}

RgbaImage contactSheet(const std::vector<RgbaImage>& tiles, const ContactSheetOptions& options) {
  if (tiles.empty()) throw InputError("contact sheet: no frames");
  const int tw = tiles[0].width, th = tiles[0].height;
  for (const RgbaImage& t : tiles)
    if (t.width != tw || t.height != th) throw InputError("contact sheet: tiles differ in size");
  const int count = static_cast<int>(tiles.size());
  const int columns = options.columns > 0 ? std::min(options.columns, count)
                                          : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  const int rows = (count + columns - 1) / columns;
  const int gap = std::max(0, options.gap);
  RgbaImage sheet;
  sheet.width = columns * tw + (columns + 1) * gap;
  sheet.height = rows * th + (rows + 1) * gap;
  sheet.pixels.resize(static_cast<size_t>(sheet.width) * sheet.height * 4);
  for (size_t p = 0; p < sheet.pixels.size(); p += 4) {
    std::copy(options.background.begin(), options.background.end(), sheet.pixels.begin() + p);
    sheet.pixels[p + 3] = 255;
  }
  for (int i = 0; i < count; ++i) {
    const int ox = gap + (i % columns) * (tw + gap), oy = gap + (i / columns) * (th + gap);
    for (int y = 0; y < th; ++y)
      for (int x = 0; x < tw; ++x) {
        const uint8_t* p = tiles[i].at(x, y);
        uint8_t* q = sheet.at(ox + x, oy + y);
        const double a = p[3] / 255.0;
        for (int c = 0; c < 3; ++c) q[c] = static_cast<uint8_t>(std::lround(p[c] * a + q[c] * (1 - a)));
      }
  }
  return sheet;
}

}  // namespace ib::render
