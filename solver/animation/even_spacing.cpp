#include "animation/even_spacing.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace ib {

namespace {

// RMS over vertices of |a_v - b_v|, in the multimesh's units.
double rmsMove(const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b) {
  return std::sqrt((a - b).rowwise().squaredNorm().mean());
}

// Whether the segment's path stays at one pose (a hold between equal marks), so there is nothing
// to space.
bool stationary(const Timeline& timeline, int segment) {
  const Eigen::VectorXd& a = timeline.marks()[segment].weights;
  const auto same = [&](const Eigen::VectorXd& w) { return (w - a).cwiseAbs().maxCoeff() < 1e-12; };
  const TimelineSegment& s = timeline.segments()[segment];
  return same(timeline.marks()[segment + 1].weights) && std::all_of(s.controls.begin(), s.controls.end(), same);
}

// Segments that get a table: kEven, none yet, not a hold (whose eased time is only 0 or 1).
bool wantsTable(const Timeline& timeline, int segment) {
  const TimelineSegment& s = timeline.segments()[segment];
  return s.spacingKind == SegmentSpacing::kEven && s.spacing.empty() && s.easing.kind != EaseKind::kHold &&
         !stationary(timeline, segment);
}

}  // namespace

bool needsEvenSpacing(const Timeline& timeline) {
  for (int k = 0; k < static_cast<int>(timeline.segments().size()); ++k)
    if (wantsTable(timeline, k)) return true;
  return false;
}

PathSamples samplePath(const Timeline& timeline, int segment, Interpolator& solver, int samples,
                       const Eigen::MatrixX2d* start, Eigen::MatrixX2d* last, const SpacingProgress& progress) {
  if (samples < 2) throw InputError("even spacing: samples: must be at least 2, not " + std::to_string(samples));
  PathSamples path;
  InterpolationResult previous;
  for (int j = 0; j < samples; ++j) {
    const double p = static_cast<double>(j) / (samples - 1);
    const Eigen::MatrixX2d* warm = j == 0 ? start : &previous.x;
    InterpolationResult r = solver.solve(timeline.pathWeights(segment, p), warm);
    if (j > 0) {
      path.steps.push_back(rmsMove(r.x, previous.x) / solver.shapeSize());
      path.pairsChange.push_back(r.heldPairs != previous.heldPairs);
    }
    previous = std::move(r);
    if (progress) progress(static_cast<double>(j + 1) / samples);
  }
  if (last) *last = previous.x;
  return path;
}

std::vector<double> spacingTable(const PathSamples& path, const EvenSpacingOptions& options) {
  if (!(options.jumpRatio > 1)) throw InputError("even spacing: jumpRatio: must be above 1");
  const std::vector<double>& steps = path.steps;
  const size_t n = steps.size();
  if (path.pairsChange.size() != n) throw std::invalid_argument("even spacing: one pairsChange per step");
  // Releases count as the pace around them: the nearest steps without one on either side,
  // linearly interpolated (the one side's where the other has none).
  std::vector<double> paced(steps);
  for (size_t j = 0; j < n; ++j) {
    if (!path.pairsChange[j]) continue;
    long before = static_cast<long>(j) - 1, after = static_cast<long>(j) + 1;
    while (before >= 0 && path.pairsChange[before]) --before;
    while (after < static_cast<long>(n) && path.pairsChange[after]) ++after;
    const bool hasBefore = before >= 0, hasAfter = after < static_cast<long>(n);
    if (hasBefore && hasAfter) {
      const double t = static_cast<double>(static_cast<long>(j) - before) / static_cast<double>(after - before);
      paced[j] = (1 - t) * steps[before] + t * steps[after];
    } else {
      paced[j] = hasBefore ? steps[before] : hasAfter ? steps[after] : 0;
    }
  }
  // Other jumps: at most jumpRatio times the longer neighbour.
  std::vector<double> capped(paced);
  for (size_t j = 0; n > 1 && j < n; ++j) {
    const double neighbour = std::max(j > 0 ? paced[j - 1] : 0.0, j + 1 < n ? paced[j + 1] : 0.0);
    capped[j] = std::min(paced[j], options.jumpRatio * neighbour);
  }
  double total = 0;
  for (double s : capped) total += s;
  if (!(total > 1e-12)) return {};
  const double floor = 1e-3 * total / static_cast<double>(n);
  std::vector<double> table{0};
  double sum = 0;
  for (double s : capped) table.push_back(sum += std::max(s, floor));
  for (double& v : table) v /= sum;
  table.back() = 1;
  return table;
}

Timeline evenSpacing(const Timeline& timeline, Interpolator& solver, const EvenSpacingOptions& options,
                     const SpacingProgress& progress) {
  if (options.samples < 2) throw InputError("even spacing: samples: must be at least 2, not " + std::to_string(options.samples));
  std::vector<TimelineSegment> segments = timeline.segments();
  const int count = static_cast<int>(segments.size());
  int todo = 0, done = 0;
  for (int k = 0; k < count; ++k) todo += wantsTable(timeline, k);
  // Consecutive segments are sampled as the stream plays them: each starts from where the last
  // ended, so a cut's held or released state carries over as it does in the frames.
  Eigen::MatrixX2d end;
  bool carried = false;
  for (int k = 0; k < count; ++k) {
    if (!wantsTable(timeline, k)) {
      carried = false;
      continue;
    }
    const SpacingProgress step = progress ? SpacingProgress([&](double f) { progress((done + f) / todo); }) : nullptr;
    const PathSamples path = samplePath(timeline, k, solver, options.samples, carried ? &end : nullptr, &end, step);
    segments[k].spacing = spacingTable(path, options);
    carried = true;
    ++done;
  }
  solver.forgetHistory();
  return Timeline(timeline.fps(), timeline.loops(), timeline.marks(), std::move(segments));
}

}  // namespace ib
