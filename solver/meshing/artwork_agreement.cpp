#include "meshing/artwork_agreement.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace ib {

namespace {

const uint8_t* pixel(const RgbaImage& image, int x, int y) { return &image.pixels[4 * (static_cast<size_t>(y) * image.width + x)]; }

// Dilates `on` (width x height) by `r` pixels in x and in y (a square window), in two passes.
std::vector<char> dilate(const std::vector<char>& on, int width, int height, int r) {
  std::vector<char> rows(on.size(), 0), out(on.size(), 0);
  for (int y = 0; y < height; ++y) {
    int last = -r - 1;  // the last set pixel at or left of x + r
    for (int x = 0; x < width + r; ++x) {
      if (x < width && on[static_cast<size_t>(y) * width + x]) last = x;
      const int c = x - r;
      if (c >= 0 && last >= c - r) rows[static_cast<size_t>(y) * width + c] = 1;
    }
  }
  for (int x = 0; x < width; ++x) {
    int last = -r - 1;
    for (int y = 0; y < height + r; ++y) {
      if (y < height && rows[static_cast<size_t>(y) * width + x]) last = y;
      const int c = y - r;
      if (c >= 0 && last >= c - r) out[static_cast<size_t>(c) * width + x] = 1;
    }
  }
  return out;
}

}  // namespace

AgreementMask agreement(const std::vector<RgbaImage>& keys, const AgreementOptions& options) {
  if (keys.empty()) throw std::invalid_argument("agreement: no keys");
  AgreementMask mask;
  mask.width = keys.front().width;
  mask.height = keys.front().height;
  for (const RgbaImage& k : keys) {
    mask.width = std::min(mask.width, k.width);
    mask.height = std::min(mask.height, k.height);
  }
  const size_t n = static_cast<size_t>(mask.width) * mask.height;
  std::vector<char> differs(n, 0);
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x)
      for (size_t k = 1; k < keys.size(); ++k)
        if (pixelDifference(pixel(keys[k], x, y), pixel(keys[0], x, y)) > options.tolerance) differs[static_cast<size_t>(y) * mask.width + x] = 1;
  const std::vector<char> near = dilate(differs, mask.width, mask.height, options.margin);
  std::vector<char> structure;
  if (options.structure > 0) {
    std::vector<char> edge(n, 0);
    for (int y = 0; y + 1 < mask.height; ++y)
      for (int x = 0; x + 1 < mask.width; ++x) {
        const uint8_t* p = pixel(keys[0], x, y);
        if (pixelDifference(p, pixel(keys[0], x + 1, y)) > 32 || pixelDifference(p, pixel(keys[0], x, y + 1)) > 32)
          edge[static_cast<size_t>(y) * mask.width + x] = 1;
      }
    structure = dilate(edge, mask.width, mask.height, options.structure);
  }
  mask.inside.assign(n, 0);
  for (int y = options.margin; y < mask.height - options.margin; ++y)  // the margin from the canvas's edge too
    for (int x = options.margin; x < mask.width - options.margin; ++x) {
      const size_t i = static_cast<size_t>(y) * mask.width + x;
      if (near[i]) continue;
      if (options.opaqueOnly && pixel(keys[0], x, y)[3] == 0) continue;
      if (!structure.empty() && !structure[i]) continue;
      mask.inside[i] = 1;
      ++mask.count;
    }
  return mask;
}

std::vector<int> artworkAnchors(const std::vector<RgbaImage>& drawings, double edgeLength, const std::vector<Eigen::Vector2d>& points,
                                const std::vector<std::array<int, 3>>& triangles, const std::vector<char>& onBoundary,
                                std::vector<char> taken) {
  AgreementOptions options;
  options.margin = static_cast<int>(std::ceil(edgeLength));
  options.opaqueOnly = true;
  options.structure = static_cast<int>(std::ceil(2 * edgeLength));
  const AgreementMask same = agreement(drawings, options);
  for (const std::array<int, 3>& t : triangles)
    for (int c = 0; c < 3; ++c)
      if (onBoundary[t[c]]) taken[t[(c + 1) % 3]] = taken[t[(c + 2) % 3]] = 1;
  std::vector<int> out;
  for (size_t v = 0; v < points.size(); ++v)
    if (!taken[v] && !onBoundary[v] && same.at(points[v])) out.push_back(static_cast<int>(v));
  return out;
}

int pixelDifference(const uint8_t* a, const uint8_t* b) {
  int d = std::abs(a[3] - b[3]);
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a[c] * a[3] - b[c] * b[3]) / 255);
  return d;
}

bool AgreementMask::at(const Eigen::Vector2d& p) const {
  const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
  return x >= 0 && y >= 0 && x < width && y < height && inside[static_cast<size_t>(y) * width + x];
}

}  // namespace ib
