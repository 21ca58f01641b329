#include "output/ghosting.h"

namespace ib::render {

namespace {

const uint8_t* pixel(const RgbaImage& image, int x, int y) { return &image.pixels[4 * (static_cast<size_t>(y) * image.width + x)]; }

}  // namespace

Ghosting ghosting(const RgbaImage& frame, const RgbaImage& drawing, const AgreementMask& mask, int threshold) {
  Ghosting g;
  long long sum = 0;
  int over = 0;
  for (int y = 0; y < mask.height && y < frame.height && y < drawing.height; ++y)
    for (int x = 0; x < mask.width && x < frame.width && x < drawing.width; ++x) {
      if (!mask.inside[static_cast<size_t>(y) * mask.width + x]) continue;
      const int d = pixelDifference(pixel(frame, x, y), pixel(drawing, x, y));
      sum += d;
      over += d > threshold;
      ++g.pixels;
    }
  if (g.pixels > 0) {
    g.mean = static_cast<double>(sum) / g.pixels;
    g.share = static_cast<double>(over) / g.pixels;
  }
  return g;
}

}  // namespace ib::render
