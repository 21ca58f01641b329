// Detail drawn inside the shapes that moved (../shared/correspondence.md): regions of flat colour
// (a stripe, an eye, a patch) matched across keys by colour, size and place, and pinned so that
// the map carries each onto itself in every key, as interior features do. Part of
// "correspondence": "artwork" (docs/drawings-to-multimesh.md, "Correspondence from the artwork").
#pragma once

#include "core/png_image.h"
#include "meshing/tracing.h"

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace ib {

struct ArtworkRegionOptions {
  int colourTolerance = 24;  // /255: largest channel difference from a region's first pixel. Default 24.
  double minArea = 6;        // px^2: smaller regions are specks. Default 6.
  double maxShare = 0.3;     // regions over this share of the drawn pixels are fills, not detail. Default 0.3.
  // px: a region's pixels this near the outline touch it (across the outline's ink line). Default 4.
  double contactReach = 4;
};

// The drawings' regions of flat colour, segmented and matched across keys once per build; what
// the build pins and holds follows from them at each edge length it tries.
class ArtworkRegions {
 public:
  // Segments every key's drawing and matches the reference key's regions in every other key: a
  // region (fully opaque pixels of one colour, 4-connected, not touching the transparent paper, its
  // centroid on itself, not of the colour of the largest region, the fill, whose pieces change
  // shape with what is around them) that every other key has exactly once (the same colour within
  // twice the tolerance, area within a factor 2.5, centroid within 0.3 of the shape's size; the
  // second best at least 0.3 costlier), and that moved (centroid or area) in some key.
  ArtworkRegions(const std::vector<RgbaImage>& drawings, int reference, const ArtworkRegionOptions& options = {});
  ~ArtworkRegions();
  ArtworkRegions(ArtworkRegions&&) noexcept;
  ArtworkRegions& operator=(ArtworkRegions&&) noexcept;

  // Points to pin, [key][pin] in drawing px: the centroid of every matched region in every key,
  // kept when every key has it at least `clearance` px from transparent paper and from every
  // centroid kept before it. (The points at the ends of a region's axes as well, carried by its
  // moments, folded chick-squash's initial map near its feet; centroids alone do not.)
  std::vector<std::vector<Eigen::Vector2d>> pins(double clearance) const;

  // Where the matched regions meet the outline: a region that comes within options.contactReach px
  // of key k's traced `outlines[k]` (outer loops and holes) at the same number of places in every
  // key, each place paired across keys by its direction from the region's centroid (the nearest
  // both ways, within 45 deg): [contact][key], points on the keys' loops (px): the two ends of the
  // stretch of outline it touches, or its middle where that stretch is shorter than 2 contactReach
  // in some key. A stripe across a body meets the outline at its two ends; knots there
  // (SharedBoundaryOptions::artworkKnots) carry the stripe's ends onto each other.
  std::vector<std::vector<Eigen::Vector2d>> contacts(const std::vector<std::vector<Outline>>& outlines) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ib
