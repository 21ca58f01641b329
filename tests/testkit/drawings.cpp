#include "testkit/drawings.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unistd.h>
#include <stdexcept>

namespace test {

namespace {

int coverage(const Inside& inside, int x, int y) {
  int hits = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) hits += inside(x + (i + 0.5) / 4, y + (j + 0.5) / 4);
  return hits;
}

}  // namespace

ib::RgbaImage drawShape(int width, int height, const Inside& inside, int r, int g, int b) {
  ib::RgbaImage image;
  image.width = width;
  image.height = height;
  image.hasAlpha = true;
  image.pixels.assign(static_cast<size_t>(width) * height * 4, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      uint8_t* p = image.at(x, y);
      p[0] = static_cast<uint8_t>(r), p[1] = static_cast<uint8_t>(g), p[2] = static_cast<uint8_t>(b);
      p[3] = static_cast<uint8_t>(std::min(255, coverage(inside, x, y) * 16));
    }
  return image;
}

ib::RgbaImage drawOpaque(int width, int height, const Inside& inside, int paper) {
  ib::RgbaImage image = drawShape(width, height, inside, 0, 0, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      uint8_t* p = image.at(x, y);
      const double a = p[3] / 255.0;  // ink (black) over paper
      p[0] = p[1] = p[2] = static_cast<uint8_t>(std::lround(paper * (1 - a)));
      p[3] = 255;
    }
  image.hasAlpha = false;
  return image;
}

Inside disc(double cx, double cy, double radius) {
  return [=](double x, double y) { return (x - cx) * (x - cx) + (y - cy) * (y - cy) < radius * radius; };
}

Inside box(double x0, double y0, double x1, double y1) {
  return [=](double x, double y) { return x > x0 && x < x1 && y > y0 && y < y1; };
}

Inside unite(Inside a, Inside b) {
  return [=](double x, double y) { return a(x, y) || b(x, y); };
}

Inside subtract(Inside a, Inside b) {
  return [=](double x, double y) { return a(x, y) && !b(x, y); };
}

std::string palettePng(int width, int height, const Inside& inside) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = PNG_FORMAT_RGBA_COLORMAP;
  image.colormap_entries = 2;
  const uint8_t colormap[8] = {255, 255, 255, 0, 200, 30, 30, 255};
  std::vector<uint8_t> index(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) index[static_cast<size_t>(y) * width + x] = inside(x + 0.5, y + 0.5);
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, index.data(), 0, colormap))
    throw std::runtime_error(image.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, index.data(), 0, colormap))
    throw std::runtime_error(image.message);
  bytes.resize(size);
  return bytes;
}

std::string scratchDirectory(const std::string& name) {
  // Per process: ctest runs test cases side by side, each in its own process.
  const auto dir = std::filesystem::temp_directory_path() / ("inbetween-test-" + name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace test
