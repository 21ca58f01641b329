// A map built before, as the start of the next one: the editor rebuilds after every small edit,
// and untangling each key from a Tutte embedding again is most of that rebuild. Each point of the
// new reference mesh is located in the previous multimesh's reference key (barycentric, the
// nearest triangle where the new shape reaches past the old) and carried into the previous
// map's other keys; after a small edit that start is nearly untangled already.
#pragma once

#include "meshing/untangle.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace ib {

struct PreviousMap {
  std::shared_ptr<const Multimesh> mesh;  // the previous build's multimesh (any topology)
  int reference = -1;                     // its key whose positions the new reference mesh is located in
  std::vector<int> keyOf;                 // [new key]: the previous mesh's key of the same name, -1: none
};

// Where the previous map puts the points of a new reference mesh, per key.
class PreviousMapStart {
 public:
  // points: the new reference mesh's positions (n x 2, px). A point farther than `reach` px from
  // every previous triangle (or a previous map without the reference key) leaves it unlocated.
  PreviousMapStart(const PreviousMap& previous, const Eigen::MatrixX2d& points, double reach);

  // True when every point was located and the previous map has key `key` (a new key's index).
  bool covers(int key) const;
  // The start for key `key` (n x 2, px): the points carried into the previous map's positions of
  // that key. Only when covers(key).
  Eigen::MatrixX2d positions(int key) const;

 private:
  const PreviousMap* previous_;
  bool located_ = false;
  std::vector<int> triangle_;                 // [point]: the previous triangle it is in (or nearest)
  std::vector<Eigen::Vector3d> barycentric_;  // [point]: its weights there (clamped: non-negative, sum 1)
};

// The vertices (n flags, 1 = in) within `rings` rings of triangles of a triangle with no
// positive area at `positions` (n x 2).
std::vector<char> foldNeighbourhood(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& positions, int rings);

// Untangles a map carried from the previous one (positions, n x 2, updated in place; `locked` as
// untangle() takes it): foldNeighbourhood(kFoldRings) first, the rest held (the carried map is
// good there, and a few free vertices converge in a few iterations); when that leaves a fold,
// every vertex not locked.
UntangleResult untangleCarried(const std::vector<Triangle>& triangles, const Eigen::MatrixX2d& rest,
                               Eigen::MatrixX2d& positions, const std::vector<char>& locked, const UntangleOptions& options);
constexpr int kFoldRings = 4;

}  // namespace ib
