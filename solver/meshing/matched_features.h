// The feature pairs the shape matching finds (`inbetween mesh --suggest`): the outline points the
// matching of outline_matching.h pairs across keys, shown to the user with a confidence so that
// what the automatic correspondence decided can be seen, and kept as features where it is right
// or corrected where it is not. (The editor's Suggest button, engine/editor/feature_suggestions.h,
// proposes corners before any feature is placed, without this matching.)
#pragma once

#include "meshing/key_shape.h"
#include "scene/scene.h"

#include <Eigen/Core>
#include <vector>

namespace ib {

struct MatchedFeature {
  std::vector<Eigen::Vector2d> at;  // [key]: the point on that key's outline, px
  double confidence = 0;            // in [0, 1]: how alike the keys' outlines turn there (1: the same corner)
  double moved = 0;                 // px: the farthest any key puts it from the reference key's point
};

struct MatchedFeatureOptions {
  double cornerAngle = 35;  // deg: the reference outline turns at least this much within `window`. Default 35.
  double window = 3;        // px along the outline on either side of a corner. Default 3.
  double minConfidence = 0.3;  // suggestions less sure than this are left out. Default 0.3.
};

// Between the scene's features (arcs as matchBoundaries makes them, corners off), every corner of
// the reference key's outline, with its match in every other key: where the shape matching puts
// it, moved to the nearby outline point (within a sixth of the arc) that turns most like it.
// Points within `window` of a feature are left out. Sorted by confidence, highest first. shapes:
// the keys' shapes after features and cuts (BuiltScene::shapes). Throws what matchBoundaries throws.
std::vector<MatchedFeature> matchedFeatures(const Scene& scene, const std::vector<KeyShape>& shapes,
                                            const MatchedFeatureOptions& options = {});

}  // namespace ib
