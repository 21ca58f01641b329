#include "output/contact_sheet.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace ib::render {

namespace {

// One output pixel's share of the source pixels along one axis: source pixels first..first+n-1
// with weights[k] = (length of source pixel first+k inside the footprint) / (footprint length).
struct Footprint {
  int first = 0;
  std::vector<double> weights;  // sum to 1
};

// The footprints of `to` output pixels over `from` source pixels: output pixel i covers source
// [i * from / to, (i + 1) * from / to) in source pixels, fractional at both ends.
std::vector<Footprint> footprints(int from, int to) {
  std::vector<Footprint> out(static_cast<size_t>(to));
  const double scale = static_cast<double>(from) / to;  // source pixels per output pixel
  for (int i = 0; i < to; ++i) {
    const double begin = static_cast<double>(i) * from / to, end = static_cast<double>(i + 1) * from / to;
    const int first = static_cast<int>(std::floor(begin));
    const int last = std::min(from, static_cast<int>(std::ceil(end)));  // one past
    out[i].first = first;
    for (int s = first; s < last; ++s) {
      const double covered = std::min<double>(end, s + 1) - std::max<double>(begin, s);
      out[i].weights.push_back(covered / scale);
    }
  }
  return out;
}

}  // namespace

RgbaImage shrink(const RgbaImage& frame, int width, int height) {
  if (frame.width < 1 || frame.height < 1) throw std::invalid_argument("contact sheet: an empty frame");
  width = std::clamp(width, 1, frame.width);
  height = std::clamp(height, 1, frame.height);
  // The area filter is separable (a footprint covers a source pixel by its x overlap times its y
  // overlap), so each output row first sums its footprint's source rows, whole rows at a time, then
  // each pixel sums its footprint's columns of that. Premultiplied, in units of 1 / 255^2: colour
  // times alpha (both 0..255), then 255 times alpha.
  const std::vector<Footprint> across = footprints(frame.width, width), down = footprints(frame.height, height);
  const size_t rowLength = static_cast<size_t>(frame.width) * 4;
  std::vector<double> source(rowLength), column(rowLength);  // one source row; the footprint's rows summed
  RgbaImage out;
  out.width = width;
  out.height = height;
  out.hasAlpha = frame.hasAlpha;
  out.pixels.resize(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    std::fill(column.begin(), column.end(), 0.0);
    for (size_t k = 0; k < down[y].weights.size(); ++k) {
      const uint8_t* p = frame.at(0, down[y].first + static_cast<int>(k));
      for (size_t i = 0; i < rowLength; i += 4) {
        for (size_t c = 0; c < 3; ++c) source[i + c] = p[i + c] * p[i + 3];
        source[i + 3] = 255 * p[i + 3];
      }
      const double w = down[y].weights[k];
      for (size_t i = 0; i < rowLength; ++i) column[i] += w * source[i];
    }
    for (int x = 0; x < width; ++x) {
      const Footprint& f = across[x];
      const double* s = &column[4 * static_cast<size_t>(f.first)];
      double sum[4] = {0, 0, 0, 0};
      for (size_t k = 0; k < f.weights.size(); ++k)
        for (size_t c = 0; c < 4; ++c) sum[c] += f.weights[k] * s[4 * k + c];
      // Back to straight alpha, 8 bits per channel; a fully transparent pixel's colour is black.
      uint8_t* q = out.at(x, y);
      for (size_t c = 0; c < 3; ++c)
        q[c] = sum[3] > 0 ? static_cast<uint8_t>(std::lround(std::clamp(sum[c] / sum[3], 0.0, 1.0) * 255)) : 0;
      q[3] = static_cast<uint8_t>(std::lround(std::clamp(sum[3] / 255, 0.0, 255.0)));
    }
  }
  return out;
}

RgbaImage contactSheet(const std::vector<RgbaImage>& tiles, const ContactSheetOptions& options) {
  if (tiles.empty()) throw std::invalid_argument("contact sheet: no frames");
  const int tw = tiles[0].width, th = tiles[0].height;
  for (const RgbaImage& t : tiles)
    if (t.width != tw || t.height != th) throw std::invalid_argument("contact sheet: tiles differ in size");
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
