#include "editor/feature_suggestions.h"

#include "core/plane_geometry.h"
#include "meshing/key_shape.h"
#include "meshing/matched_features.h"
#include "meshing/outline_corners.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ib::editor {

namespace {

constexpr double kMaxCost = 0.25;  // a pair farther apart than this (in bounding boxes, plus turning / pi) is none

struct Corner {
  Eigen::Vector2d at;          // drawing pixels
  Eigen::Vector2d normalized;  // in the key's outline's bounding box, [0, 1]^2
  double turn = 0;
};

std::vector<Corner> cornersOf(const Polyline& outline, double clearance, const std::vector<Eigen::Vector2d>& features) {
  const ArcLengthLoop loop(outline);
  Eigen::Vector2d lo = outline.front(), hi = outline.front();
  for (const Eigen::Vector2d& p : outline) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Eigen::Vector2d size = (hi - lo).cwiseMax(Eigen::Vector2d(1, 1));
  std::vector<Corner> out;
  for (const OutlineCorner& c : outlineCorners(loop, OutlineCornerOptions{})) {
    const Eigen::Vector2d at = loop.at(c.s);
    bool free = true;
    for (const Eigen::Vector2d& f : features) free = free && (f - at).norm() > clearance;
    if (free) out.push_back({at, (at - lo).cwiseQuotient(size), c.turn});
  }
  return out;
}

double cost(const Corner& a, const Corner& b) {
  if ((a.turn > 0) != (b.turn > 0)) return std::numeric_limits<double>::infinity();
  return (a.normalized - b.normalized).norm() + 0.5 * std::abs(a.turn - b.turn) / 3.14159265358979;
}

// The index of the corner of `in` cheapest to pair with `c`, or -1 past kMaxCost.
int nearest(const Corner& c, const std::vector<Corner>& in) {
  int best = -1;
  double bestCost = kMaxCost;
  for (size_t i = 0; i < in.size(); ++i)
    if (cost(c, in[i]) < bestCost) bestCost = cost(c, in[i]), best = static_cast<int>(i);
  return best;
}

}  // namespace

std::vector<FeatureSuggestion> suggestFeatures(const DocumentMarks& marks, const std::vector<std::vector<Outline>>& outlines,
                                               double clearance) {
  const size_t m = marks.keys.size();
  if (m < 2 || outlines.size() != m) return {};
  std::vector<std::vector<Corner>> corners(m);
  for (size_t k = 0; k < m; ++k) {
    if (outlines[k].empty() || outlines[k].front().outer.size() < 3) return {};
    std::vector<Eigen::Vector2d> placed;
    for (const auto& [name, p] : marks.keys[k].features) placed.push_back(p);
    corners[k] = cornersOf(outlines[k].front().outer, clearance, placed);
  }
  const size_t reference = static_cast<size_t>(std::max(0, marks.keyIndex(marks.reference)));
  std::vector<FeatureSuggestion> out;
  for (const Corner& c : corners[reference]) {
    // In every other key, the cheapest corner whose cheapest in the reference key is this one.
    FeatureSuggestion s;
    s.at.resize(m);
    s.at[reference] = c.at;
    s.turn = c.turn;
    bool everywhere = true;
    for (size_t k = 0; k < m && everywhere; ++k) {
      if (k == reference) continue;
      const int pick = nearest(c, corners[k]);
      everywhere = pick >= 0 && &corners[reference][static_cast<size_t>(nearest(corners[k][static_cast<size_t>(pick)], corners[reference]))] == &c;
      if (everywhere) s.at[k] = corners[k][static_cast<size_t>(pick)].at;
    }
    if (everywhere) out.push_back(s);
  }
  return out;
}

std::vector<FeatureSuggestion> matchedSuggestions(const Scene& scene, const std::vector<std::vector<Outline>>& outlines) {
  bool featured = false;
  for (const KeySpec& key : scene.keys) featured = featured || !key.features.empty();
  if (!featured || outlines.size() != scene.keys.size()) return {};
  std::vector<KeyShape> shapes;
  for (int k = 0; k < static_cast<int>(scene.keys.size()); ++k)
    shapes.push_back(buildKeyShape(scene, k, outlines[static_cast<size_t>(k)], KeyShapeOptions{}));
  std::vector<FeatureSuggestion> out;
  for (const MatchedFeature& matched : matchedFeatures(scene, shapes)) {
    FeatureSuggestion s;
    s.at = matched.at;
    s.confidence = matched.confidence;
    s.moved = matched.moved;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace ib::editor
