// The editor's Suggest button. Once the keys carry features, what the shape matching pairs
// between them (matchedSuggestions, meshing/matched_features.h). Before, features proposed where
// every key's outline has a corner that corresponds, on the outer loop of each key's first shape:
// corners are found as the mesher finds them (meshing/outline_corners.h); a reference key's
// corner pairs with another key's when each is the other's cheapest match: same turning sign,
// cost = distance in the outlines' bounding boxes (normalized to [0, 1]) plus half the turning
// difference over pi, at most 0.25. (Not the mesher's pairing by arc fraction between features:
// with no features yet, and outlines of different lengths, that pairs a square's corner with an
// arch's leg.) The user accepts or drops each. CPU only.
#pragma once

#include "editor/editor_marks.h"
#include "scene/scene.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ib::editor {

struct FeatureSuggestion {
  std::vector<Eigen::Vector2d> at;  // [key]: on its outline, drawing pixels
  double turn = 0;                  // radians, the reference key's corner's turning (> 0 convex)
  // From the shape matching between the features placed (matchedSuggestions): how sure, in
  // [0, 1], and how far the farthest key moved it (px); -1 and 0 from the corner pairing.
  double confidence = -1;
  double moved = 0;
};

// outlines[k]: key k's traced outlines (EditorSession::outlines). Corners closer than `clearance`
// px to a feature a key places already are not proposed. Keys without an outline give none.
std::vector<FeatureSuggestion> suggestFeatures(const DocumentMarks& marks, const std::vector<std::vector<Outline>>& outlines,
                                               double clearance = 6);

// Once the keys carry features: the feature pairs the shape matching finds between them
// (meshing/matched_features.h: the reference key's outline corners and where the matching puts
// them in every key, with a confidence), so the user sees what "correspondence": "artwork"
// decides. scene: the document's; outlines[k]: key k's traced outlines. Empty when no key has a
// feature yet; InputError when the keys' shapes do not match up (their features differ).
std::vector<FeatureSuggestion> matchedSuggestions(const Scene& scene, const std::vector<std::vector<Outline>>& outlines);

}  // namespace ib::editor
