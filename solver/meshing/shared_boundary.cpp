#include "meshing/shared_boundary.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

namespace ib {

namespace {

std::string list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + inQuotes(n);
  return out.empty() ? "no features" : out;
}

// The loop's features in walking order starting at point `start`, with their point indices.
std::vector<std::pair<std::string, int>> featuresFrom(const ShapeLoop& loop, int start) {
  std::vector<std::pair<std::string, int>> out;
  const int n = static_cast<int>(loop.points.size());
  for (int i = 0; i < n; ++i) {
    const int p = (start + i) % n;
    if (!loop.features[p].empty()) out.push_back({loop.features[p], p});
  }
  return out;
}

std::vector<std::string> names(const std::vector<std::pair<std::string, int>>& features) {
  std::vector<std::string> out;
  for (const auto& f : features) out.push_back(f.first);
  return out;
}

Eigen::Vector2d centroid(const Polyline& loop) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : loop) c += p;
  return c / std::max<size_t>(loop.size(), 1);
}

// Arc length on `target` where a rigid motion of `source` sampled from its start fits best.
// Near-ties (within 1% of the loops' spread; a circle fits any start) go to the smallest rotation,
// so symmetric loops keep their orientation and nested loops start on the same side.
double alignedStart(const ArcLengthLoop& source, const ArcLengthLoop& target, int samples) {
  std::vector<Eigen::Vector2d> a(samples);
  Eigen::Vector2d ca = Eigen::Vector2d::Zero();
  for (int i = 0; i < samples; ++i) ca += a[i] = source.at(source.length() * i / samples);
  ca /= samples;
  double aa = 0;
  for (auto& p : a) aa += (p -= ca).squaredNorm();
  const int shifts = 4 * samples;
  std::vector<double> cost(shifts), angle(shifts);
  std::vector<Eigen::Vector2d> b(samples);
  double spread = aa;
  for (int s = 0; s < shifts; ++s) {
    const double start = target.length() * s / shifts;
    Eigen::Vector2d cb = Eigen::Vector2d::Zero();
    for (int i = 0; i < samples; ++i) cb += b[i] = target.at(start + target.length() * i / samples);
    cb /= samples;
    double bb = 0, dot = 0, cross = 0;
    for (int i = 0; i < samples; ++i) {
      const Eigen::Vector2d q = b[i] - cb;
      bb += q.squaredNorm();
      dot += a[i].dot(q);
      cross += a[i].x() * q.y() - a[i].y() * q.x();
    }
    cost[s] = aa + bb - 2 * std::hypot(dot, cross);  // residual after the best rotation
    angle[s] = std::abs(std::atan2(cross, dot));
    spread = aa + bb;
  }
  const double lowest = *std::min_element(cost.begin(), cost.end());
  int best = 0;
  for (int s = 0; s < shifts; ++s)
    if (cost[s] <= lowest + 0.01 * spread && (cost[best] > lowest + 0.01 * spread || angle[s] < angle[best])) best = s;
  return target.length() * best / shifts;
}

class Matcher {
 public:
  Matcher(const Scene& scene, const std::vector<KeyShape>& shapes, const SharedBoundaryOptions& options)
      : scene_(scene), shapes_(shapes), options_(options), ref_(scene.reference),
        file_(std::filesystem::path(scene.file).filename().string()) {}

  SharedBoundary run() {
    const KeyShape& ref = shapes_[ref_];
    out_.keys.resize(shapes_.size());
    for (size_t l = 0; l < ref.loops.size(); ++l) addArcs(static_cast<int>(l));
    for (size_t k = 0; k < shapes_.size(); ++k) matchKey(static_cast<int>(k));
    pairCutSides();
    countSegments();
    return std::move(out_);
  }

 private:
  InputError mismatch(const std::string& what) const { return InputError(file_ + ": loops do not match: " + what); }
  std::string keyName(int k) const { return "key " + inQuotes(shapes_[k].key); }

  void addArcs(int loop) {
    const auto features = featuresFrom(shapes_[ref_].loops[loop], 0);
    std::vector<int> arcs;
    if (features.empty()) {
      out_.arcs.push_back({loop, 0, "", "", 1, -1, {}});
      arcs.push_back(static_cast<int>(out_.arcs.size()) - 1);
    }
    for (size_t i = 0; i < features.size(); ++i) {
      out_.arcs.push_back({loop, static_cast<int>(i), features[i].first, features[(i + 1) % features.size()].first, 1, -1, {}});
      arcs.push_back(static_cast<int>(out_.arcs.size()) - 1);
    }
    out_.loopArcs.push_back(arcs);
  }

  // Finds key k's loop for every reference loop, checks its features, records arc starts.
  void matchKey(int k) {
    const KeyShape& ref = shapes_[ref_];
    const KeyShape& key = shapes_[k];
    KeyBoundary& kb = out_.keys[k];
    kb.loops.resize(ref.loops.size());
    kb.arcStarts.resize(ref.loops.size());
    std::vector<bool> used(key.loops.size(), false);
    std::vector<int> featureless;
    for (size_t l = 0; l < ref.loops.size(); ++l) {
      const auto want = featuresFrom(ref.loops[l], 0);
      if (want.empty()) {
        featureless.push_back(static_cast<int>(l));
        continue;
      }
      const auto [kl, kp] = findFeature(key, want[0].first);
      if (kl < 0) throw mismatch(keyName(k) + " has no feature " + inQuotes(want[0].first));
      const auto have = featuresFrom(key.loops[kl], kp);
      checkSameFeatures(k, names(want), names(have), key);
      used[kl] = true;
      kb.loops[l] = ArcLengthLoop(key.loops[kl].points);
      for (const auto& f : have) kb.arcStarts[l].push_back(kb.loops[l].parameterOfPoint(f.second));
    }
    matchFeatureless(k, featureless, used);
  }

  void checkSameFeatures(int k, const std::vector<std::string>& want, const std::vector<std::string>& have,
                         const KeyShape& key) const {
    if (want == have) return;
    for (const std::string& f : want)
      if (std::find(have.begin(), have.end(), f) == have.end()) {
        const auto [loop, point] = findFeature(key, f);
        (void)point;
        throw mismatch("in " + keyName(ref_) + " one loop carries " + list(want) + ", but in " + keyName(k) + " feature " +
                       inQuotes(f) + (loop < 0 ? " is missing" : " lies on another loop (with " +
                                                                  list(names(featuresFrom(key.loops[loop], 0))) + ")"));
      }
    for (const std::string& f : have)
      if (std::find(want.begin(), want.end(), f) == want.end())
        throw mismatch("in " + keyName(k) + " one loop carries " + list(have) + ", but in " + keyName(ref_) +
                       " feature " + inQuotes(f) + " is not on the loop with " + list(want));
    throw mismatch("the loop with " + list(want) + " runs " + list(want) + " in " + keyName(ref_) + " but " + list(have) +
                   " in " + keyName(k) + " (same features, different order)");
  }

  // Pairs the loops without features by nearest centroid and size among loops of the same kind (outer or
  // hole) and starts each at its best rigid alignment with the reference loop.
  void matchFeatureless(int k, const std::vector<int>& refLoops, std::vector<bool>& used) {
    const KeyShape& ref = shapes_[ref_];
    const KeyShape& key = shapes_[k];
    std::vector<int> candidates;
    for (size_t l = 0; l < key.loops.size(); ++l)
      if (!used[l]) candidates.push_back(static_cast<int>(l));
    if (candidates.size() != refLoops.size())
      throw mismatch(keyName(ref_) + " has " + std::to_string(refLoops.size()) + " loop(s) without features, but " +
                     keyName(k) + " has " + std::to_string(candidates.size()) +
                     " (place features to say which loop becomes which)");
    for (int l : refLoops) {
      const bool outer = loopArea(ref.loops[l].points) > 0;
      const Eigen::Vector2d c = centroid(ref.loops[l].points);
      const double size = std::sqrt(std::abs(loopArea(ref.loops[l].points)));
      int best = -1;
      double bestDistance = std::numeric_limits<double>::infinity();
      for (int cand : candidates) {
        if (used[cand] || (loopArea(key.loops[cand].points) > 0) != outer) continue;
        // Nested loops share a centre: tell them apart by size too.
        const double d = (centroid(key.loops[cand].points) - c).norm() +
                         std::abs(std::sqrt(std::abs(loopArea(key.loops[cand].points))) - size);
        if (d < bestDistance) bestDistance = d, best = cand;
      }
      if (best < 0)
        throw mismatch(keyName(k) + " has no " + (outer ? "outline" : "hole") + " without features to match the one of " +
                       keyName(ref_) + " around " + std::to_string(static_cast<int>(c.x())) + ", " +
                       std::to_string(static_cast<int>(c.y())));
      used[best] = true;
      KeyBoundary& kb = out_.keys[k];
      kb.loops[l] = ArcLengthLoop(key.loops[best].points);
      const ArcLengthLoop refLoop(ref.loops[l].points);
      kb.arcStarts[l] = {k == ref_ ? 0.0 : alignedStart(refLoop, kb.loops[l], options_.alignmentSamples)};
    }
  }

  // The two sides of every cut are partner arcs; they are collocated in the keys that draw it.
  void pairCutSides() {
    std::map<std::string, int> arcFrom;
    for (size_t a = 0; a < out_.arcs.size(); ++a)
      if (!out_.arcs[a].from.empty()) arcFrom[out_.arcs[a].from] = static_cast<int>(a);
    for (size_t k = 0; k < scene_.keys.size(); ++k)
      for (const CutSpec& cut : scene_.keys[k].cuts) {
        const std::vector<std::string> f = cutFeatureNames(cut.name, cut.kind);
        // Side starts: notch right and tip; split start.right and end.left; slit start and end.
        const std::string first = cut.kind == CutKind::kNotch ? f[1] : cut.kind == CutKind::kSplit ? f[1] : f[0];
        const std::string second = cut.kind == CutKind::kNotch ? f[2] : cut.kind == CutKind::kSplit ? f[2] : f[1];
        const int a = arcFrom.at(first), b = arcFrom.at(second);
        out_.arcs[a].partner = b;
        out_.arcs[b].partner = a;
        out_.arcs[a].closedIn.push_back(static_cast<int>(k));
        out_.arcs[b].closedIn.push_back(static_cast<int>(k));
      }
  }

  // Enough segments that no key's boundary edge is longer than the edge length; partners equal;
  // at least three per loop.
  void countSegments() {
    for (size_t a = 0; a < out_.arcs.size(); ++a) {
      double longest = 0;
      for (size_t k = 0; k < shapes_.size(); ++k)
        longest = std::max(longest, out_.arcLength(static_cast<int>(k), static_cast<int>(a)));
      out_.arcs[a].segments = std::max(1, static_cast<int>(std::ceil(longest / options_.edgeLength - 1e-9)));
    }
    for (BoundaryArc& arc : out_.arcs)
      if (arc.partner >= 0) arc.segments = std::max(arc.segments, out_.arcs[arc.partner].segments);
    for (const std::vector<int>& loop : out_.loopArcs) {
      int total = 0;
      for (int a : loop) total += out_.arcs[a].segments;
      for (size_t i = 0; total < 3; ++i, ++total) {
        BoundaryArc& arc = out_.arcs[loop[i % loop.size()]];
        ++arc.segments;
        if (arc.partner >= 0) out_.arcs[arc.partner].segments = arc.segments;
      }
    }
  }

  const Scene& scene_;
  const std::vector<KeyShape>& shapes_;
  SharedBoundaryOptions options_;
  int ref_;
  std::string file_;
  SharedBoundary out_;
};

}  // namespace

double SharedBoundary::arcLength(int key, int arc) const {
  const BoundaryArc& a = arcs[arc];
  const KeyBoundary& kb = keys[key];
  const std::vector<double>& starts = kb.arcStarts[a.loop];
  const size_t i = a.indexInLoop;
  const double length = kb.loops[a.loop].length();
  if (starts.size() == 1) return length;
  double span = starts[(i + 1) % starts.size()] - starts[i];
  if (span <= 0) span += length;
  return span;
}

Eigen::Vector2d SharedBoundary::at(int key, int arc, double u) const {
  const BoundaryArc& a = arcs[arc];
  const KeyBoundary& kb = keys[key];
  return kb.loops[a.loop].at(kb.arcStarts[a.loop][a.indexInLoop] + u * arcLength(key, arc));
}

double SharedBoundary::chordDeviation(int key, int arc, double u0, double u1, double u2) const {
  const BoundaryArc& a = arcs[arc];
  const KeyBoundary& kb = keys[key];
  const double start = kb.arcStarts[a.loop][a.indexInLoop], length = arcLength(key, arc);
  return kb.loops[a.loop].chordDeviation({start + u0 * length, start + u1 * length, start + u2 * length});
}

SharedBoundary matchBoundaries(const Scene& scene, const std::vector<KeyShape>& shapes,
                               const SharedBoundaryOptions& options) {
  return Matcher(scene, shapes, options).run();
}

}  // namespace ib
