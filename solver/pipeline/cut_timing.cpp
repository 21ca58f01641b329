#include "pipeline/cut_timing.h"

#include "multimesh/multimesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace ib {

namespace {

// Distance from p to the polyline (drawing pixels).
double distanceTo(const Polyline& line, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Eigen::Vector2d a = line[i], d = line[i + 1] - line[i];
    const double t = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (a + t * d - p).norm());
  }
  return best;
}

// A cut's own timing by name: the first key that gives each field (the parser checks they agree).
std::map<std::string, CutRelease> ownTimings(const Scene& scene) {
  std::map<std::string, CutRelease> own;
  for (const KeySpec& key : scene.keys)
    for (const CutSpec& cut : key.cuts) {
      CutRelease& t = own[cut.name];
      if (cut.release && std::isnan(t.release)) t.release = *cut.release;
      if (cut.releaseWindow && std::isnan(t.window)) t.window = *cut.releaseWindow;
    }
  return own;
}

}  // namespace

std::vector<CutRelease> cutReleases(const Scene& scene, const Multimesh& mesh) {
  const std::map<std::string, CutRelease> own = ownTimings(scene);
  const bool any = std::any_of(own.begin(), own.end(), [](const auto& t) {
    return !std::isnan(t.second.release) || !std::isnan(t.second.window);
  });
  if (!any) return {};
  std::vector<CutRelease> perTerm;
  for (int k = 0; k < mesh.keyCount() && k < static_cast<int>(scene.keys.size()); ++k) {
    const Eigen::MatrixX2d& X = mesh.keyPositions(k);
    for (const CohesivePair& p : mesh.cohesivePairs(k)) {
      const Eigen::Vector2d mid = 0.25 * (X.row(p.a) + X.row(p.b) + X.row(p.c) + X.row(p.d)).transpose();
      const CutSpec* nearest = nullptr;
      double best = std::numeric_limits<double>::infinity();
      for (const CutSpec& cut : scene.keys[k].cuts) {
        const double d = distanceTo(cut.points, mid);
        if (d < best) best = d, nearest = &cut;
      }
      perTerm.push_back(nearest ? own.at(nearest->name) : CutRelease{});
    }
  }
  return perTerm;
}

double openWeight(const Scene& scene, const std::string& cut, int frame) {
  const Eigen::VectorXd w = scene.timeline.weights(scene.timeline.frameTime(frame));
  double open = 0;
  for (size_t k = 0; k < scene.keys.size() && static_cast<Eigen::Index>(k) < w.size(); ++k) {
    bool closed = false;
    for (const CutSpec& c : scene.keys[k].cuts) closed = closed || c.name == cut;
    if (!closed) open += w(static_cast<Eigen::Index>(k));
  }
  return open;
}

std::vector<CutEvent> cutEvents(const Scene& scene) {
  std::vector<CutEvent> events;
  const CohesiveParams& params = scene.interpolation.cohesive;
  if (params.timing != CutTiming::kRelease) return events;
  const std::map<std::string, CutRelease> own = ownTimings(scene);
  const Timeline& timeline = scene.timeline;
  for (const auto& [name, timing] : own) {
    const double release = std::isnan(timing.release) ? params.release : timing.release;
    double before = openWeight(scene, name, 0);
    for (int f = 1; f < timeline.frameCount(); ++f) {
      const double now = openWeight(scene, name, f);
      if (before < release && now >= release) events.push_back({name, timeline.frameTime(f), f, false});
      if (before >= release && now < release) events.push_back({name, timeline.frameTime(f), f, true});
      before = now;
    }
  }
  std::stable_sort(events.begin(), events.end(), [](const CutEvent& a, const CutEvent& b) { return a.frame < b.frame; });
  return events;
}

}  // namespace ib
