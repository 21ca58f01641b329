// Where the keys' drawings are the same (../shared/correspondence.md): the pixels where every key's
// artwork agrees, away from any that differ, and among them those near drawn structure (an edge of
// the artwork), where agreement is evidence that the drawings did not move there. Flat colour
// agrees wherever two shapes overlap, moved or not, so it alone says nothing.
#pragma once

#include "core/png_image.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace ib {

// A mask over the drawings' common pixels.
struct AgreementMask {
  int width = 0, height = 0;  // the smallest key's size (pixels outside it are never in)
  std::vector<char> inside;   // [y * width + x]
  int count = 0;              // pixels inside
  bool at(const Eigen::Vector2d& p) const;  // the pixel under drawing point p (px, y down); false outside
};

struct AgreementOptions {
  int tolerance = 2;  // /255: largest difference of a premultiplied RGBA channel between two keys that still agree. Default 2.
  int margin = 3;     // px: a pixel is inside only if every pixel within this many (in x and in y) agrees. Default 3.
  bool opaqueOnly = false;  // only pixels every key draws (alpha > 0): the artwork, not the paper around it. Default false.
  // px: also only pixels with an edge of the artwork (two neighbouring pixels of the first key
  // more than 32/255 apart) within this many, in x and in y; 0: no such condition. Default 0.
  int structure = 0;
};

// Throws std::invalid_argument for no keys.
AgreementMask agreement(const std::vector<RgbaImage>& keys, const AgreementOptions& options = {});

// The artwork's anchors of a mesh over the reference key's drawing (`points` in its pixels): the
// vertices where every key's drawing is the same within `edgeLength` (rounded up) and drawn
// structure lies within twice that, except those on the boundary, next to it (their boundary
// neighbour sits where the outlines match, which may be a pixel off the identity, and the
// triangle between them would have no room) and `taken`. In increasing order.
std::vector<int> artworkAnchors(const std::vector<RgbaImage>& drawings, double edgeLength, const std::vector<Eigen::Vector2d>& points,
                                const std::vector<std::array<int, 3>>& triangles, const std::vector<char>& onBoundary,
                                std::vector<char> taken);

// Largest premultiplied RGBA channel difference of two straight RGBA pixels, 0-255.
int pixelDifference(const uint8_t* a, const uint8_t* b);

}  // namespace ib
