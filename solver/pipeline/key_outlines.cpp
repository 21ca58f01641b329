#include "pipeline/key_outlines.h"

#include "core/plane_geometry.h"
#include "core/png_image.h"

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
  LoopPoint best;
  best.point = p;
  const auto consider = [&](const Polyline& loop) {
    const LoopPoint q = nearestOnLoop(loop, p);
    if (q.distance < best.distance) best = q;
  };
  for (const Outline& o : outlines) {
    consider(o.outer);
    for (const Polyline& hole : o.holes) consider(hole);
  }
  return best.point;
}

}  // namespace ib
