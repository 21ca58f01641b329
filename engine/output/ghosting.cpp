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

int edgePixels(const RgbaImage& image, int threshold, int margin) {
  const int w = image.width, h = image.height;
  // Paper (alpha under 128) grown by `margin` in x, then in y: a square of side 2 margin + 1.
  std::vector<char> paper(static_cast<size_t>(w) * h), grown(paper.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) paper[static_cast<size_t>(y) * w + x] = pixel(image, x, y)[3] < 128;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int d = -margin; d <= margin && !grown[static_cast<size_t>(y) * w + x]; ++d)
        grown[static_cast<size_t>(y) * w + x] = x + d >= 0 && x + d < w && paper[static_cast<size_t>(y) * w + x + d];
  paper = grown;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int d = -margin; d <= margin && !grown[static_cast<size_t>(y) * w + x]; ++d)
        grown[static_cast<size_t>(y) * w + x] = y + d >= 0 && y + d < h && paper[static_cast<size_t>(y + d) * w + x];
  int count = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (grown[static_cast<size_t>(y) * w + x]) continue;
      const bool right = x + 1 < w && pixelDifference(pixel(image, x, y), pixel(image, x + 1, y)) > threshold;
      const bool down = y + 1 < h && pixelDifference(pixel(image, x, y), pixel(image, x, y + 1)) > threshold;
      count += right || down;
    }
  return count;
}

}  // namespace ib::render
