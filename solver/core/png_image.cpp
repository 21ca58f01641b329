#include "core/png_image.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <png.h>

namespace ib {

RgbaImage readPng(const std::string& path) {
  // Read through memory: a missing file then gets the same clear message as everywhere else.
  return decodePng(readFile(path), path);
}

RgbaImage decodePng(const std::string& bytes, const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    throw InputError(path + ": not a readable PNG (" + image.message + ")");
  RgbaImage out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.hasAlpha = (image.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  // Checked before anything is allocated: a header can declare any size. 8192 x 8192 (256 MiB as
  // RGBA) is four times the largest artwork the tool is for; tracing and meshing more would not
  // finish in reasonable time anyway.
  constexpr double kMostPixels = 8192.0 * 8192.0;
  if (out.width <= 0 || out.height <= 0 || static_cast<double>(out.width) * out.height > kMostPixels) {
    png_image_free(&image);
    throw InputError(path + ": PNG size " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                     " is out of range (at most 8192 x 8192 pixels in all): scale the drawing down");
  }
  image.format = PNG_FORMAT_RGBA;
  out.pixels.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr))
    throw InputError(path + ": corrupt PNG (" + image.message + ")");
  return out;
}

std::string encodePng(const RgbaImage& in) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(in.width);
  image.height = static_cast<png_uint_32>(in.height);
  image.format = PNG_FORMAT_RGBA;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, in.pixels.data(), 0, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + image.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, in.pixels.data(), 0, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + image.message);
  bytes.resize(size);
  return bytes;
}

void writePng(const std::string& path, const RgbaImage& image) { writeFileAtomically(path, encodePng(image)); }

}  // namespace ib
