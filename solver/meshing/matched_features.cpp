#include "meshing/matched_features.h"

#include "meshing/outline_matching.h"
#include "meshing/shared_boundary.h"

#include <algorithm>
#include <cmath>

namespace ib {

namespace {

// The signed angle (deg) by which polyline p turns at sample i, between the chords from h samples
// before and to h samples after; 0 within h samples of either end.
double turning(const std::vector<Eigen::Vector2d>& p, int i, int h) {
  const int n = static_cast<int>(p.size());
  if (i - h < 0 || i + h >= n) return 0;
  const Eigen::Vector2d a = p[i] - p[i - h], b = p[i + h] - p[i];
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)) * 180 / M_PI;
}

// Samples per window of `window` px along a polyline of n samples over `length` px, at least 1.
int samplesIn(double window, double length, int n) {
  return std::max(1, static_cast<int>(std::lround(window * (n - 1) / std::max(length, 1e-9))));
}

}  // namespace

std::vector<MatchedFeature> matchedFeatures(const Scene& scene, const std::vector<KeyShape>& shapes,
                                            const MatchedFeatureOptions& options) {
  SharedBoundaryOptions bo;
  bo.corners = CornerHandling::kOff;  // arcs from feature to feature
  const SharedBoundary boundary = matchBoundaries(scene, shapes, bo);
  const int keys = static_cast<int>(boundary.keys.size()), reference = scene.reference;
  const OutlineMatchOptions matching;
  std::vector<MatchedFeature> out;
  for (size_t a = 0; a < boundary.arcs.size(); ++a) {
    if (boundary.arcs[a].partner >= 0) continue;  // cut sides follow the cut
    const int arc = static_cast<int>(a);
    double longest = 0;
    for (int k = 0; k < keys; ++k) longest = std::max(longest, boundary.arcLength(k, arc));
    const int n = std::clamp(static_cast<int>(std::ceil(longest / matching.spacing)) + 1, 8, matching.maxSamples);
    std::vector<std::vector<Eigen::Vector2d>> samples(keys, std::vector<Eigen::Vector2d>(n));
    for (int k = 0; k < keys; ++k)
      for (int i = 0; i < n; ++i) samples[k][i] = boundary.atFraction(k, arc, static_cast<double>(i) / (n - 1));
    std::vector<std::vector<double>> matched(keys);  // [key][reference sample]: fraction along the key's arc
    for (int k = 0; k < keys; ++k)
      if (k != reference) matched[k] = matchByShape(samples[reference], samples[k], matching);
    const std::vector<Eigen::Vector2d>& ref = samples[reference];
    const int h = samplesIn(options.window, boundary.arcLength(reference, arc), n);
    std::vector<double> turn(n);
    for (int i = 0; i < n; ++i) turn[i] = turning(ref, i, h);
    for (int i = h; i + h < n; ++i) {
      if (std::abs(turn[i]) < options.cornerAngle) continue;
      bool peak = true;  // the sharpest within h samples (the first of equals)
      for (int j = std::max(0, i - h); j <= std::min(n - 1, i + h) && peak; ++j)
        peak = j == i || std::abs(turn[j]) < std::abs(turn[i]) || (std::abs(turn[j]) == std::abs(turn[i]) && j > i);
      if (!peak) continue;
      MatchedFeature s;
      s.at.resize(keys);
      s.at[reference] = ref[i];
      s.confidence = 1;
      for (int k = 0; k < keys; ++k) {
        if (k == reference) continue;
        const int hk = samplesIn(options.window, boundary.arcLength(k, arc), n);
        if (2 * hk >= n - 1) {  // the key's arc is too short to turn within the window: no match there
          s.confidence = 0;
          break;
        }
        const int j0 = static_cast<int>(std::lround(matched[k][i] * (n - 1)));
        const int reach = std::max(hk, n / 6);
        int best = std::clamp(j0, hk, n - 1 - hk);
        double bestScore = 1e300;
        for (int j = std::max(hk, j0 - reach); j <= std::min(n - 1 - hk, j0 + reach); ++j) {
          // Most like the reference's corner, nearest the match: 15 deg for the whole reach.
          const double score = std::abs(turning(samples[k], j, hk) - turn[i]) + 15.0 * std::abs(j - j0) / reach;
          if (score < bestScore) bestScore = score, best = j;
        }
        s.at[k] = samples[k][best];
        s.confidence = std::min(s.confidence, std::exp(-std::abs(turning(samples[k], best, hk) - turn[i]) / 20.0));
        s.moved = std::max(s.moved, (s.at[k] - ref[i]).norm());
      }
      if (s.confidence >= options.minConfidence) out.push_back(std::move(s));
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const MatchedFeature& a, const MatchedFeature& b) { return a.confidence > b.confidence; });
  return out;
}

}  // namespace ib
