#include "pipeline/key_outlines.h"

#include "core/png_image.h"

#include <algorithm>
#include <cmath>

namespace ib {

KeyOutlines::KeyOutlines(const Scene& scene) : tracing_(scene.tracing) {
  for (const KeySpec& key : scene.keys) keys_[key.name] = {key.drawing, key.holes};
}

void KeyOutlines::add(const std::string& key, const std::string& drawing, const Polyline& holes) {
  keys_[key] = {drawing, holes};
  traced_.erase(key);
}

void KeyOutlines::remove(const std::string& key) {
  keys_.erase(key);
  traced_.erase(key);
}

const std::vector<Outline>* KeyOutlines::of(const std::string& key) {
  const auto spec = keys_.find(key);
  if (spec == keys_.end()) return nullptr;
  auto it = traced_.find(key);
  if (it == traced_.end()) {
    const auto& [drawing, holes] = spec->second;
    const ShapeMask mask = shapeMask(readPng(drawing), tracing_, holes, drawing);
    it = traced_.emplace(key, traceOutlines(mask, tracing_, drawing)).first;
  }
  return &it->second;
}

Eigen::Vector2d nearestOnOutlines(const std::vector<Outline>& outlines, const Eigen::Vector2d& p) {
  Eigen::Vector2d best = p;
  double bestDistance = INFINITY;
  const auto visit = [&](const Polyline& loop) {
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector2d a = loop[i], b = loop[(i + 1) % loop.size()], d = b - a;
      const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      const Eigen::Vector2d q = a + t * d;
      if ((q - p).norm() < bestDistance) bestDistance = (q - p).norm(), best = q;
    }
  };
  for (const Outline& o : outlines) {
    visit(o.outer);
    for (const Polyline& hole : o.holes) visit(hole);
  }
  return best;
}

}  // namespace ib
