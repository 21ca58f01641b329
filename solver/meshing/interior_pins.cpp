#include "meshing/interior_pins.h"

#include "meshing/artwork_agreement.h"
#include "meshing/artwork_regions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ib {

// Key k's pinned interior points, in the order of ReferenceMesh::interior: its interior features
// (by name: every key places the same), then round each one with a radius r a ring of
// max(6, ceil(2 pi r / e)) points at distance r, e the edge length. Each ring point sits at the same
// offset from its feature in every key, so the disc's triangles are translated copies of each
// other in every key and the detail drawn there moves as one piece. Then regions[k], if any.
std::vector<Eigen::Vector2d> interiorPoints(const Scene& scene, int k, double edgeLength, const KeyPoints& regions) {
  const KeySpec& key = scene.keys[k];
  std::vector<Eigen::Vector2d> out;
  for (const auto& [name, p] : key.interiorFeatures) out.push_back(p);
  for (const auto& [name, r] : key.interiorRadii) {
    const int n = std::max(6, static_cast<int>(std::ceil(2 * M_PI * r / edgeLength)));
    for (int j = 0; j < n; ++j) {
      const double angle = 2 * M_PI * j / n;
      out.push_back(key.interiorFeatures.at(name) + r * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    }
  }
  if (!regions.empty()) out.insert(out.end(), regions[static_cast<size_t>(k)].begin(), regions[static_cast<size_t>(k)].end());
  return out;
}

InteriorPins interiorPins(const Scene& scene, const ReferenceMesh& mesh, double edgeLength, const KeyPoints& regions) {
  // mesh.interior holds interiorPoints' vertices: the features and rings, then the regions' pins.
  const size_t regionCount = regions.empty() ? 0 : regions[0].size();
  if (mesh.interior.size() < regionCount) throw std::logic_error("interiorPins: the mesh lacks the regions' pins");
  const size_t featureCount = mesh.interior.size() - regionCount;
  InteriorPins pins;
  pins.vertices.assign(mesh.interior.begin(), mesh.interior.begin() + static_cast<std::ptrdiff_t>(featureCount));
  for (int k = 0; k < static_cast<int>(scene.keys.size()); ++k) pins.targets.push_back(interiorPoints(scene, k, edgeLength));
  std::vector<char> pinned(mesh.points.size(), 0);
  for (int v : mesh.interior) pinned[v] = 1;
  const KeySpec& reference = scene.keys[scene.reference];
  for (const auto& [name, r] : reference.interiorRadii) {
    const Eigen::Vector2d centre = reference.interiorFeatures.at(name);
    for (size_t v = 0; v < mesh.points.size(); ++v) {
      if (pinned[v] || mesh.tags[v].arc >= 0 || (mesh.points[v] - centre).norm() >= r) continue;
      pinned[v] = 1;
      pins.vertices.push_back(static_cast<int>(v));
      for (size_t k = 0; k < scene.keys.size(); ++k)
        pins.targets[k].push_back(scene.keys[k].interiorFeatures.at(name) + (mesh.points[v] - centre));
    }
  }
  pins.features = pins.vertices.size();
  // The regions' pins after the features: placed in the initial map, moved by Comesh like the
  // anchors (kept there, they left slivers on five bundled scenes).
  for (size_t p = 0; p < regionCount; ++p) {
    pins.vertices.push_back(mesh.interior[featureCount + p]);
    for (size_t k = 0; k < scene.keys.size(); ++k) pins.targets[k].push_back(regions[k][p]);
  }
  return pins;
}

// The artwork's anchors (meshing/artwork_agreement.h: artworkAnchors), each held where the
// reference key has it, in every key: what did not change in the drawings does not move.
void anchorArtwork(const std::vector<RgbaImage>& drawings, const ReferenceMesh& mesh, double edgeLength, InteriorPins& pins) {
  std::vector<char> onBoundary(mesh.points.size(), 0), taken(mesh.points.size(), 0);
  for (size_t v = 0; v < mesh.points.size(); ++v) onBoundary[v] = mesh.tags[v].arc >= 0;
  for (int v : pins.vertices) taken[v] = 1;
  for (int v : artworkAnchors(drawings, edgeLength, mesh.points, mesh.triangles, onBoundary, taken)) {
    pins.vertices.push_back(v);
    for (auto& targets : pins.targets) targets.push_back(mesh.points[v]);
    ++pins.anchors;
  }
}

std::vector<int> deepAnchors(const ReferenceMesh& mesh, const InteriorPins& pins) {
  const size_t n = mesh.points.size();
  std::vector<char> deep(n, 0);
  for (size_t p = pins.vertices.size() - pins.anchors; p < pins.vertices.size(); ++p) deep[pins.vertices[p]] = 1;
  for (int ring = 0; ring < kAnchorRings; ++ring) {  // strip the anchors next to a vertex that is not one
    const std::vector<char> before = deep;
    for (const auto& t : mesh.triangles)
      for (int c = 0; c < 3; ++c)
        if (!before[t[c]]) deep[t[(c + 1) % 3]] = deep[t[(c + 2) % 3]] = 0;
  }
  std::vector<int> out;
  for (size_t v = 0; v < n; ++v)
    if (deep[v]) out.push_back(static_cast<int>(v));
  return out;
}

KeyPoints regionPins(const Scene& scene, const ArtworkRegions& artwork, const std::vector<KeyShape>& shapes,
                     double edgeLength, const std::vector<Eigen::Vector2d>& clearOf, double clearance) {
  KeyPoints pins = artwork.pins(kRegionClearance * edgeLength);
  // None near an interior feature or its disc (within the clearance of its rim), a fold, an
  // outline or a cut.
  const KeySpec& reference = scene.keys[scene.reference];
  std::vector<char> keep(pins.empty() ? 0 : pins[0].size(), 1);
  for (size_t p = 0; p < keep.size(); ++p) {
    for (const auto& [name, at] : reference.interiorFeatures) {
      const auto radius = reference.interiorRadii.find(name);
      const double r = radius == reference.interiorRadii.end() ? 0.0 : radius->second;
      keep[p] = keep[p] && (pins[static_cast<size_t>(scene.reference)][p] - at).norm() >= r + kRegionClearance * edgeLength;
    }
    for (size_t k = 0; k < pins.size(); ++k) {
      for (const Eigen::Vector2d& fold : clearOf) keep[p] = keep[p] && (pins[k][p] - fold).norm() >= clearance;
      // Clear of the outline and of the cuts, as interior features must be (checkInteriorFeatures).
      keep[p] = keep[p] && distanceToLoops(shapes[k].loops, pins[k][p]).first >= kRegionClearance * edgeLength;
    }
  }
  KeyPoints out(pins.size());
  for (size_t k = 0; k < pins.size(); ++k)
    for (size_t p = 0; p < keep.size(); ++p)
      if (keep[p]) out[k].push_back(pins[k][p]);
  return out;
}

}  // namespace ib
