// PNG drawings in and pictures out, through libpng's simplified API: every colour type and bit
// depth (palette with transparency, grey, 16-bit) is read as 8-bit RGBA.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ib {

struct RgbaImage {
  int width = 0, height = 0;
  bool hasAlpha = false;        // the file carried transparency (an alpha channel or tRNS)
  std::vector<uint8_t> pixels;  // width * height * 4 bytes, rows top to bottom, RGBA

  const uint8_t* at(int x, int y) const { return pixels.data() + 4 * (static_cast<size_t>(y) * width + x); }
  uint8_t* at(int x, int y) { return pixels.data() + 4 * (static_cast<size_t>(y) * width + x); }
};

// Throws InputError naming the path: missing, unreadable, not a PNG, corrupt or truncated.
RgbaImage readPng(const std::string& path);
// The same from the file's bytes; `path` names them in messages.
RgbaImage decodePng(const std::string& bytes, const std::string& path);

// PNG file bytes of an RGBA image (for tests and pictures).
std::string encodePng(const RgbaImage& image);

// Writes the image atomically. Throws InputError naming the path when it cannot be written.
void writePng(const std::string& path, const RgbaImage& image);

}  // namespace ib
