// The reference mesh's vertices placed in every key before the rest is mapped (multimesh_builder):
// the interior features and their discs, and with "correspondence": "artwork" the artwork's anchors.
#pragma once

#include "core/png_image.h"
#include "meshing/artwork_regions.h"
#include "meshing/key_shape.h"
#include "meshing/reference_mesh.h"
#include "scene/scene.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

// The reference mesh's pinned interior vertices and where each sits in every key (px): the
// vertices of mesh.interior at interiorPoints, then every other vertex inside the disc of a feature
// with a radius, at the same offset from the feature as in the reference key (the mesher's and the
// split's points there too, so that the whole disc is a translated copy in every key).
// Vertices placed in every key before the rest is mapped: the interior features (and their
// discs), then, with "correspondence": "artwork", the moved regions' pins (regionPins) and the
// artwork's anchors (anchorArtwork), placed in the initial map; Comesh keeps the features and the
// anchors deep inside the anchored region (deepAnchors), and moves the rest.
struct InteriorPins {
  std::vector<int> vertices;
  std::vector<std::vector<Eigen::Vector2d>> targets;  // [key][pin]
  size_t features = 0;  // the first `features` pins are interior features: Comesh keeps them
  size_t anchors = 0;   // the last `anchors` pins are the artwork's anchors (deepAnchors)
};

using KeyPoints = std::vector<std::vector<Eigen::Vector2d>>;  // [key][point], px

// Key k's pinned interior points, in the order of ReferenceMesh::interior (px): its interior
// features, then a ring round each one with a radius (interiorPins says how), then regions[k]
// (regionPins; empty: none).
std::vector<Eigen::Vector2d> interiorPoints(const Scene& scene, int k, double edgeLength, const KeyPoints& regions = {});
InteriorPins interiorPins(const Scene& scene, const ReferenceMesh& mesh, double edgeLength, const KeyPoints& regions = {});

// With "correspondence": "artwork", the moved regions' pins (meshing/artwork_regions.h), at least
// kRegionClearance edge lengths from the paper, from each other, from every key's outline and cuts
// (shapes: BuiltScene::shapes) and from the interior features' discs: pinned in every key's initial map like interior features, so a stripe or an eye that
// moved is carried onto itself.
constexpr double kRegionClearance = 1.5;
// None within `clearance` px of a point of clearOf (px, in any key: where a key folded before).
KeyPoints regionPins(const Scene& scene, const ArtworkRegions& artwork, const std::vector<KeyShape>& shapes,
                     double edgeLength, const std::vector<Eigen::Vector2d>& clearOf = {}, double clearance = 0);
// Adds the artwork's anchors (meshing/artwork_agreement.h: artworkAnchors) to pins, each held where
// the reference key has it, in every key: what did not change in the drawings does not move.
void anchorArtwork(const std::vector<RgbaImage>& drawings, const ReferenceMesh& mesh, double edgeLength, InteriorPins& pins);

// The artwork's anchors Comesh keeps where they are (ComeshBoundary::pinned): those at least
// kAnchorRings edges from any vertex that is not an anchor. The rings between stay free, for
// Comesh to even out the triangles where the still part meets the moving one. On the drawn test
// scenes (docs/benchmarks.md, "bench ghost"): every anchor free, lean-mirror's drawn pixels were
// 15.5/255 off on average; one ring, 3.1, with its smallest angle after Comesh 27 -> 10 deg; two,
// 4.4 and 13 deg; three, 6.3 and 20 deg.
constexpr int kAnchorRings = 2;
std::vector<int> deepAnchors(const ReferenceMesh& mesh, const InteriorPins& pins);

}  // namespace ib
