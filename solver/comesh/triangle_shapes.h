// What Comesh Optimization's remeshing passes ask of every triangle in every key, all from its
// squared edge lengths: its largest angle and the edge facing it (flips), which edges are too long
// (splits), and which are too short or face too small an angle (collapses). A vertex step moves
// one key, so keys are recomputed one at a time, in one pass over all triangles that vectorizes;
// a triangle whose corners changed (a flip, a split, a collapse) is recomputed in every key, found
// by comparing corners block by block (memcmp), so that the passes read the answers with no test
// per triangle. The passes ask about all keys at once, so that is kept combined as well.
#pragma once

#include "comesh/comesh_mesh.h"

#include <cmath>
#include <vector>

namespace ib {

// The largest angle of a triangle with squared edge lengths l0, l1, l2 (edge i: corner i to
// corner i + 1) faces the longest edge, which goes to `edge`; returns its cosine, by the law of
// cosines. Selects instead of branches and indexing, so that loops calling it vectorize.
inline double largestAngleCosine(double l0, double l1, double l2, int& edge) {
  const bool first = l0 >= l1 && l0 >= l2, second = !first && l1 >= l2;
  const double longest = first ? l0 : (second ? l1 : l2);
  const double other = first ? l1 : (second ? l2 : l0), third = first ? l2 : (second ? l0 : l1);
  edge = first ? 0 : (second ? 1 : 2);
  return (other + third - longest) / (2 * std::sqrt(other * third));
}

// Bounds per key (px): lengths are compared squared, angles by the square of their cosine.
struct TriangleShapeBounds {
  std::vector<double> shortLength;  // [key]: shorter edges are collapse candidates
  std::vector<double> longLength;   // [key]: longer edges are split candidates
  double thinAngle = 10;            // degrees: an edge facing a smaller angle is a collapse candidate
};

class TriangleShapes {
 public:
  TriangleShapes(const ComeshMesh& mesh, const TriangleShapeBounds& bounds);

  // Key k's positions moved: it is recomputed for every triangle at the next refresh().
  void keyMoved(int k);
  // Brings the cache to the mesh's triangle count, recomputes the keys that moved and, in every
  // key, the triangles whose corners changed or that were added (looked for only when the mesh's
  // topologyVersion moved). The queries below answer for the mesh as it was at the last refresh().
  void refresh();

  // Over all keys: the cosine of triangle t's largest angle in the key where it is largest (the
  // first such key), or 0 when it is not obtuse in any key, or 1 without keys.
  double worstCosine(int t) const { return worstCosine_[t]; }
  // The edge facing that angle.
  int worstEdge(int t) const { return combined_[t] & 3; }
  // Bit i: edge i is long in every key.
  int longInEveryKey(int t) const { return (combined_[t] >> 2) & 7; }
  // Bit i: edge i is short in every key.
  int shortInEveryKey(int t) const { return (combined_[t] >> 5) & 7; }
  // Bit i: edge i faces a thin angle in every key.
  int thinInEveryKey(int t) const { return (combined_[t] >> 8) & 7; }

  // Per key. Cosine of triangle t's largest angle in key k, or 0 when that angle is not obtuse.
  double largestCosine(int t, int k) const { return cosine_[k][t]; }
  // The edge facing that angle (i: corner i -> corner i + 1).
  int largestEdge(int t, int k) const { return flags_[k][t] & 3; }
  // Bit i: edge i of triangle t is longer than the key's longLength.
  int longEdges(int t, int k) const { return (flags_[k][t] >> 2) & 7; }
  // Bit i: edge i is shorter than the key's shortLength.
  int shortEdges(int t, int k) const { return (flags_[k][t] >> 5) & 7; }
  // Bit i: edge i faces an angle smaller than thinAngle.
  int thinEdges(int t, int k) const { return (flags_[k][t] >> 8) & 7; }

 private:
  void recompute(int t);
  // Recomputes every triangle whose corners differ from those it was computed for.
  void syncCorners();
  void resize(size_t count);
  void computeKey(int k, size_t first, size_t end);
  void combineKeys(size_t first, size_t end);

  const ComeshMesh& mesh_;
  std::vector<double> shortSquared_, longSquared_;  // [key]: bounds squared (px^2)
  double thinCosine_;                               // cosine of thinAngle
  std::vector<std::vector<double>> cosine_;         // [key][triangle]: see largestCosine
  std::vector<std::vector<int>> flags_;             // [key][triangle]: bits 0-1 largest edge,
                                                    // 2-4 long, 5-7 short, 8-10 thin edges
  std::vector<double> worstCosine_;                 // [triangle]: see worstCosine
  std::vector<int> combined_;                       // [triangle]: flags_ over all keys: the
                                                    // worst key's edge, masks and-ed
  std::vector<Triangle> corners_;                   // [triangle]: the corners last computed for
  std::vector<char> stale_;                         // [key]: positions moved since computed
  long syncedVersion_ = -1;                         // the mesh's topologyVersion at the last syncCorners
};

}  // namespace ib
