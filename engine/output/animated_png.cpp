#include "output/animated_png.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

namespace ib::render {

namespace {

// CRC-32 of PNG chunks (ISO 3309, polynomial 0xedb88320), over the chunk type and data.
uint32_t crc32(const std::string& bytes) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xffffffffu;
  for (unsigned char b : bytes) c = table[(c ^ b) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

std::string bigEndian32(uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
}

std::string bigEndian16(uint16_t v) { return {static_cast<char>(v >> 8), static_cast<char>(v)}; }

std::string chunk(const std::string& type, const std::string& data) {
  const std::string body = type + data;
  return bigEndian32(static_cast<uint32_t>(data.size())) + body + bigEndian32(crc32(body));
}

struct Chunk {
  std::string type, data;
};

// The chunks of PNG file bytes (after the 8-byte signature), in order.
std::vector<Chunk> chunks(const std::string& png) {
  std::vector<Chunk> out;
  size_t at = 8;
  while (at + 12 <= png.size()) {
    const auto byte = [&](size_t i) { return static_cast<uint32_t>(static_cast<unsigned char>(png[i])); };
    const uint32_t length = byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
    out.push_back({png.substr(at + 4, 4), png.substr(at + 8, length)});
    at += 12 + length;
  }
  return out;
}

// fcTL: the frame's sequence number, size, offset (0, 0), delay, no disposal, replacing the canvas.
std::string frameControl(uint32_t sequence, const RgbaImage& frame, int milliseconds) {
  return chunk("fcTL", bigEndian32(sequence) + bigEndian32(frame.width) + bigEndian32(frame.height) + bigEndian32(0) +
                           bigEndian32(0) + bigEndian16(static_cast<uint16_t>(milliseconds)) + bigEndian16(1000) +
                           std::string(1, '\0') + std::string(1, '\0'));
}

}  // namespace

std::string encodeAnimatedPng(const std::vector<RgbaImage>& frames, int frameMilliseconds) {
  if (frames.empty()) throw std::invalid_argument("encodeAnimatedPng: no frames");
  for (const RgbaImage& f : frames)
    if (f.width != frames[0].width || f.height != frames[0].height)
      throw std::invalid_argument("encodeAnimatedPng: frames of different sizes");
  const int delay = std::max(1, std::min(frameMilliseconds, 65535));
  std::string out = "\x89PNG\r\n\x1a\n";
  uint32_t sequence = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    std::string data;  // the frame's image data: its IDAT chunks' contents, in order
    for (const Chunk& c : chunks(encodePng(frames[i]))) {
      if (i == 0 && c.type == "IHDR") {
        out += chunk("IHDR", c.data);
        out += chunk("acTL", bigEndian32(static_cast<uint32_t>(frames.size())) + bigEndian32(0));  // 0 plays: forever
      }
      if (c.type == "IDAT") data += c.data;
    }
    out += frameControl(sequence++, frames[i], delay);
    out += i == 0 ? chunk("IDAT", data) : chunk("fdAT", bigEndian32(sequence++) + data);
  }
  return out + chunk("IEND", "");
}

}  // namespace ib::render
