#include "meshing/shared_boundary.h"

#include "core/error.h"
#include "meshing/boundary_sampling.h"
#include "meshing/outline_matching.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdio>
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

bool isPiece(const Polyline& loop) { return loopArea(loop) > 0; }

// How far apart two loops are for pairing: centroids, and sizes (nested loops share a centre).
double loopDistance(const Polyline& a, const Polyline& b) {
  return (centroid(a) - centroid(b)).norm() + std::abs(std::sqrt(std::abs(loopArea(a))) - std::sqrt(std::abs(loopArea(b))));
}

}  // namespace

std::string describeLoop(const Polyline& loop) {
  const double area = loopArea(loop);
  Eigen::AlignedBox2d box;
  for (const auto& p : loop) box.extend(p);
  const Eigen::Vector2d c = box.isEmpty() ? Eigen::Vector2d(0, 0) : Eigen::Vector2d(box.center());
  char text[128];
  std::snprintf(text, sizeof text, "%s around (%.0f, %.0f), %.0f px\u00b2",
                area > 0 ? "piece" : std::abs(area) < 1e-6 ? "slit" : "hole", c.x(), c.y(), std::abs(area));
  return text;
}

namespace {

const char* const kTopologyDoc = " (docs/scene-format.md, \"When the keys' topology differs\")";

std::string count(size_t n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

// Key `more` has featureless loops of one kind (pieces or holes) that key `fewer` lacks: which, where, and
// the cut or drawing fix that makes the topology match.
std::string extraLoops(const std::string& more, const std::string& fewer, bool pieces, size_t moreCount,
                       size_t fewerCount, const std::vector<const Polyline*>& extras) {
  const std::string kind = pieces ? "piece" : "hole";
  std::string out = "key " + inQuotes(more) + " has " + (extras.size() == 1 ? "a " + kind : count(extras.size(), kind)) +
                    " that key " + inQuotes(fewer) + " does not (of the " + kind + "s without features, " + inQuotes(more) +
                    " has " + std::to_string(moreCount) + " and " + inQuotes(fewer) + " " + std::to_string(fewerCount) + "): ";
  for (size_t i = 0; i < extras.size() && i < 3; ++i) out += (i ? "; " : "") + describeLoop(*extras[i]);
  if (extras.size() > 3) out += "; ...";
  if (pieces)
    return out + ". If it is part of a piece of key " + inQuotes(fewer) + " that comes apart, draw a \"split\" cut in key " +
           inQuotes(fewer) + " where the pieces separate and place its features in key " + inQuotes(more) +
           "; if it should not be there, erase it from key " + inQuotes(more) + "'s drawing";
  return out + ". If the hole opens where key " + inQuotes(fewer) + " is solid, draw a \"slit\" cut in key " +
         inQuotes(fewer) + " where it opens and place its features in key " + inQuotes(more) + "; if key " +
         inQuotes(fewer) + " has it open to the outside, draw a \"split\" cut in key " + inQuotes(more) +
         " from the hole to the outline; if it should not be there, fill it in key " + inQuotes(more) + "'s drawing";
}

// Arc length on `target` where a linear map (an affine one: with translation) of `source`
// sampled from its start fits best. Near-ties (within 1% of the loops' spread) go to the map
// with the smallest rotation (its polar part's angle): a circle fits any start and keeps its
// orientation, nested loops start on the same side, and a squash or a stretch (a tall oval to a
// wide one, which a rotation by 90 deg fits about as well as the stretch does) is matched as
// drawn, not turned a quarter. Maps that mirror (negative determinant) are not taken.
double alignedStart(const ArcLengthLoop& source, const ArcLengthLoop& target, int samples) {
  Polyline a(samples), b(samples);
  for (int i = 0; i < samples; ++i) a[i] = source.at(source.length() * i / samples);
  const int shifts = 4 * samples;
  constexpr double kMirrored = std::numeric_limits<double>::infinity();
  std::vector<double> cost(shifts, kMirrored), angle(shifts, 0);
  double spread = 0;
  for (int s = 0; s < shifts; ++s) {
    const double start = target.length() * s / shifts;
    for (int i = 0; i < samples; ++i) b[i] = target.at(start + target.length() * i / samples);
    const std::optional<AffineFit> fit = affineFit(a, b);
    if (!fit) return 0;  // a degenerate source (a line): any start
    spread = fit->fromSpread + fit->toSpread;
    if (fit->linear.determinant() <= 0) continue;
    cost[s] = fit->residual;
    angle[s] = fit->rotation();
  }
  const double lowest = *std::min_element(cost.begin(), cost.end());
  if (lowest == kMirrored) return 0;  // only mirroring maps: any start
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
    placeCornerKnots(out_, ref_, options_);
    if (options_.correspondence == OutlineCorrespondence::kArtwork) {
      placeArtworkKnots(out_, options_);
      placeShapeKnots(out_, ref_, options_);
    }
    placeCurveKnots(out_, options_);
    countSegments(out_, ref_, options_.edgeLength);
    return std::move(out_);
  }

 private:
  InputError mismatch(const std::string& what) const { return InputError(file_ + ": outlines do not match: " + what); }
  std::string keyName(int k) const { return "key " + inQuotes(shapes_[k].key); }

  void addArcs(int loop) {
    const auto features = featuresFrom(shapes_[ref_].loops[loop], 0);
    std::vector<int> arcs;
    if (features.empty()) {
      out_.arcs.push_back({loop, 0, "", "", 1, -1, {}, {}, {}});
      arcs.push_back(static_cast<int>(out_.arcs.size()) - 1);
    }
    for (size_t i = 0; i < features.size(); ++i) {
      out_.arcs.push_back({loop, static_cast<int>(i), features[i].first, features[(i + 1) % features.size()].first, 1, -1, {}, {}, {}});
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
        if (findFeature(key, f).first < 0)
          throw mismatch("in " + keyName(ref_) + " one outline carries " + list(want) + ", but " + keyName(k) +
                         " has no feature " + inQuotes(f));
        throw apart(ref_, k, want[0], f);
      }
    for (const std::string& f : have)
      if (std::find(want.begin(), want.end(), f) == want.end()) throw apart(k, ref_, have[0], f);
    throw mismatch("the " + describeLoop(shapes_[ref_].loops[findFeature(shapes_[ref_], want[0]).first].points) +
                   " runs " + list(want) + " in " + keyName(ref_) + " but " + list(have) + " in " + keyName(k) +
                   " (same features, different order): place them in the same order along the outline in every key "
                   "(a cut's left and right are as seen walking in)");
  }

  // Features `first` and `f` lie on one loop in key `one` but on two in key `two`: the topology differs
  // there (a split is missing) or `f` is placed on the wrong outline.
  InputError apart(int one, int two, const std::string& first, const std::string& f) const {
    const auto loopOf = [&](int k, const std::string& name) -> const ShapeLoop& {
      return shapes_[k].loops[findFeature(shapes_[k], name).first];
    };
    const ShapeLoop& joined = loopOf(one, first);
    const ShapeLoop &a = loopOf(two, first), &b = loopOf(two, f);
    const std::string cut = isPiece(a.points) && isPiece(b.points)
                                ? "a \"split\" cut in " + keyName(one) + " where its piece comes apart into the two of " +
                                      keyName(two)
                                : "a \"split\" cut in " + keyName(two) + " from its hole to the outline, where " +
                                      keyName(one) + " is open to the outside";
    return mismatch("in " + keyName(one) + " " + inQuotes(first) + " and " + inQuotes(f) + " are on one " +
                    describeLoop(joined.points) + " (with " + list(names(featuresFrom(joined, 0))) + "), but in " +
                    keyName(two) + " " + inQuotes(f) + " is on a " + describeLoop(b.points) + " (with " +
                    list(names(featuresFrom(b, 0))) + ") and " + inQuotes(first) + " on a " + describeLoop(a.points) +
                    ". If the keys' topology differs there, " + cut + " makes it match; if " + inQuotes(f) +
                    " is on the wrong outline, move it in one of the keys" + kTopologyDoc);
  }

  // Pairs the loops without features with the reference key's, pieces with pieces and holes with holes, by
  // nearest centroid and size, and starts each at its best rigid alignment with the reference loop. Counts
  // that differ are an extra hole or piece in one key; pairings as good either way round need features.
  void matchFeatureless(int k, const std::vector<int>& refLoops, std::vector<bool>& used) {
    const KeyShape& ref = shapes_[ref_];
    const KeyShape& key = shapes_[k];
    std::array<std::vector<int>, 2> want, have;  // [pieces, holes]
    for (int l : refLoops) want[isPiece(ref.loops[l].points) ? 0 : 1].push_back(l);
    for (size_t l = 0; l < key.loops.size(); ++l)
      if (!used[l]) have[isPiece(key.loops[l].points) ? 0 : 1].push_back(static_cast<int>(l));
    std::string extra;
    for (int kind = 0; kind < 2; ++kind)
      if (want[kind].size() != have[kind].size()) {
        const bool refMore = want[kind].size() > have[kind].size();
        const KeyShape &more = refMore ? ref : key, &fewer = refMore ? key : ref;
        const std::vector<int>& fewerLoops = refMore ? have[kind] : want[kind];
        std::vector<int> left = refMore ? want[kind] : have[kind];
        for (int l : fewerLoops) left.erase(left.begin() + nearest(fewer.loops[l].points, more, left));
        std::vector<const Polyline*> extras;
        for (int l : left) extras.push_back(&more.loops[l].points);
        extra += (extra.empty() ? "" : "; and ") + extraLoops(more.key, fewer.key, kind == 0, std::max(want[kind].size(), have[kind].size()),
                                                             fewerLoops.size(), extras);
      }
    if (!extra.empty()) throw mismatch(extra + kTopologyDoc);
    for (int kind = 0; kind < 2; ++kind) {
      std::vector<int> match, left = have[kind];  // match[i]: key k's loop for want[kind][i]
      for (int l : want[kind]) {
        const size_t i = nearest(ref.loops[l].points, key, left);
        match.push_back(left[i]);
        left.erase(left.begin() + i);
      }
      if (k != ref_) improveAndCheck(k, want[kind], match);
      for (size_t i = 0; i < match.size(); ++i) {
        const int l = want[kind][i];
        used[match[i]] = true;
        KeyBoundary& kb = out_.keys[k];
        kb.loops[l] = ArcLengthLoop(key.loops[match[i]].points);
        const ArcLengthLoop refLoop(ref.loops[l].points);
        kb.arcStarts[l] = {k == ref_ ? 0.0 : alignedStart(refLoop, kb.loops[l], options_.alignmentSamples)};
      }
    }
  }

  // Index into `among` of key `shape`'s loop nearest to `loop`.
  static size_t nearest(const Polyline& loop, const KeyShape& shape, const std::vector<int>& among) {
    size_t best = 0;
    for (size_t i = 1; i < among.size(); ++i)
      if (loopDistance(loop, shape.loops[among[i]].points) < loopDistance(loop, shape.loops[among[best]].points)) best = i;
    return best;
  }

  // Swaps pairs of the greedy pairing while that is clearly better; a swap about as good as the pairing
  // (within 5% of the loops' sizes) means the keys do not say which loop becomes which.
  void improveAndCheck(int k, const std::vector<int>& refLoops, std::vector<int>& match) const {
    const auto cost = [&](size_t i, int cand) {
      return loopDistance(shapes_[ref_].loops[refLoops[i]].points, shapes_[k].loops[cand].points);
    };
    for (int pass = 0, swapped = 1; swapped && pass < 8; ++pass) {
      swapped = 0;
      for (size_t i = 0; i < match.size(); ++i)
        for (size_t j = i + 1; j < match.size(); ++j) {
          const double size = std::sqrt(std::abs(loopArea(shapes_[ref_].loops[refLoops[i]].points))) +
                              std::sqrt(std::abs(loopArea(shapes_[ref_].loops[refLoops[j]].points)));
          const double gain = cost(i, match[i]) + cost(j, match[j]) - cost(i, match[j]) - cost(j, match[i]);
          if (gain > 0.05 * size) {
            std::swap(match[i], match[j]);
            swapped = 1;
          } else if (gain > -0.05 * size) {
            const auto at = [&](int key, int l) { return describeLoop(shapes_[key].loops[l].points); };
            throw mismatch(keyName(k) + "'s " + at(k, match[i]) + " and " + at(k, match[j]) + " fit " + keyName(ref_) +
                           "'s " + at(ref_, refLoops[i]) + " and " + at(ref_, refLoops[j]) +
                           " about as well either way round: place a feature on each of them, in every key, to say "
                           "which becomes which" + kTopologyDoc);
          }
        }
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

double SharedBoundary::fraction(int key, int arc, double u) const {
  const std::vector<double>& knot = arcs[arc].knots;
  if (knot.empty()) return u;
  const std::vector<double>& f = keys[key].knotFractions[arc];
  const size_t j = std::upper_bound(knot.begin(), knot.end(), u) - knot.begin();  // knots at or before u
  const double u0 = j > 0 ? knot[j - 1] : 0, u1 = j < knot.size() ? knot[j] : 1;
  const double f0 = j > 0 ? f[j - 1] : 0, f1 = j < knot.size() ? f[j] : 1;
  return u1 > u0 ? f0 + (u - u0) / (u1 - u0) * (f1 - f0) : f0;
}

int SharedBoundary::knotAt(int arc, double u) const {
  const std::vector<double>& knots = arcs[arc].knots;
  for (size_t j = 0; j < knots.size(); ++j)
    if (std::abs(knots[j] - u) < 1e-12) return static_cast<int>(j);
  return -1;
}

Eigen::Vector2d SharedBoundary::at(int key, int arc, double u) const { return atFraction(key, arc, fraction(key, arc, u)); }

Eigen::Vector2d SharedBoundary::atFraction(int key, int arc, double f) const {
  const BoundaryArc& a = arcs[arc];
  const KeyBoundary& kb = keys[key];
  return kb.loops[a.loop].at(kb.arcStarts[a.loop][a.indexInLoop] + f * arcLength(key, arc));
}

double SharedBoundary::chordDeviation(int key, int arc, double u0, double u1, double u2) const {
  const BoundaryArc& a = arcs[arc];
  const KeyBoundary& kb = keys[key];
  const double start = kb.arcStarts[a.loop][a.indexInLoop], length = arcLength(key, arc);
  const auto along = [&](double u) { return start + fraction(key, arc, u) * length; };
  return kb.loops[a.loop].chordDeviation({along(u0), along(u1), along(u2)});
}

SharedBoundary matchBoundaries(const Scene& scene, const std::vector<KeyShape>& shapes,
                               const SharedBoundaryOptions& options) {
  return Matcher(scene, shapes, options).run();
}

}  // namespace ib
