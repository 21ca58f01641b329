// The keys' traced outlines, as the mesher traces them (the drawing's mask with the key's hole
// points: meshing/multimesh_builder.cpp), each traced once on first use; and snapping a point onto
// them. What `edit --apply` and the editor window snap features to. CPU only.
#pragma once

#include "meshing/tracing.h"
#include "scene/scene.h"

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace ib {

class KeyOutlines {
 public:
  // The scene's keys (drawing paths as the scene resolved them) and its tracing options.
  explicit KeyOutlines(const Scene& scene);
  // A key added since, or one whose drawing changed (with its hole points, if any): traced again
  // on next use.
  void add(const std::string& key, const std::string& drawing, const Polyline& holes = {});
  void remove(const std::string& key);
  // The key's outlines; nullptr for a key it does not know. InputError when its drawing cannot be
  // read or has no shape.
  const std::vector<Outline>* of(const std::string& key);

 private:
  TracingOptions tracing_;
  std::map<std::string, std::pair<std::string, Polyline>> keys_;  // key -> drawing path, hole points
  std::map<std::string, std::vector<Outline>> traced_;
};

// The nearest point to p (drawing pixels) on any loop of `outlines`, outer or hole; p itself
// when there are none.
Eigen::Vector2d nearestOnOutlines(const std::vector<Outline>& outlines, const Eigen::Vector2d& p);

}  // namespace ib
