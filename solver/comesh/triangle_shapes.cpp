#include "comesh/triangle_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ib {

namespace {

constexpr double kPi = 3.14159265358979323846;

// No triangle has these corners: a slot holding them is computed when first asked for.
constexpr Triangle kUncomputed = {-2, -2, -2};

// One triangle (p0, p1, p2) in one key: edges e_i = p_(i+1) - p_i, squared lengths l_i. Written
// with selects instead of branches and indexing so that the loop over triangles vectorizes.
struct Shape {
  double cosine;
  int flags;
};
inline Shape triangleShape(double x0, double y0, double x1, double y1, double x2, double y2, double short2,
                           double long2, double thinCosine) {
  const double ex0 = x1 - x0, ey0 = y1 - y0, ex1 = x2 - x1, ey1 = y2 - y1, ex2 = x0 - x2, ey2 = y0 - y2;
  const double l0 = ex0 * ex0 + ey0 * ey0, l1 = ex1 * ex1 + ey1 * ey1, l2 = ex2 * ex2 + ey2 * ey2;
  int flags = 0;
  const double cosine = largestAngleCosine(l0, l1, l2, flags);
  flags |= (l0 > long2) << 2 | (l1 > long2) << 3 | (l2 > long2) << 4;
  flags |= (l0 < short2) << 5 | (l1 < short2) << 6 | (l2 < short2) << 7;
  // Edge i faces the angle at p_(i+2), between p_i - p_(i+2) = e_(i+2) and p_(i+1) - p_(i+2) =
  // -e_(i+1): thin when dot / (|e_(i+2)| |e_(i+1)|) > thinCosine, compared squared on the side of
  // thinCosine's sign.
  const double c2 = thinCosine * thinCosine;
  const double dot0 = -(ex2 * ex1 + ey2 * ey1), limit0 = c2 * l2 * l1;
  const double dot1 = -(ex0 * ex2 + ey0 * ey2), limit1 = c2 * l0 * l2;
  const double dot2 = -(ex1 * ex0 + ey1 * ey0), limit2 = c2 * l1 * l0;
  const bool acute = thinCosine >= 0;
  const bool thin0 = acute ? (dot0 > 0 && dot0 * dot0 > limit0) : (dot0 >= 0 || dot0 * dot0 < limit0);
  const bool thin1 = acute ? (dot1 > 0 && dot1 * dot1 > limit1) : (dot1 >= 0 || dot1 * dot1 < limit1);
  const bool thin2 = acute ? (dot2 > 0 && dot2 * dot2 > limit2) : (dot2 >= 0 || dot2 * dot2 < limit2);
  flags |= thin0 << 8 | thin1 << 9 | thin2 << 10;
  return {std::min(cosine, 0.0), flags};
}

// Triangles [first, end) of one key, corners three ints each. The outputs alias nothing read
// (restrict), which lets the loop vectorize with gathered loads.
void shapeRange(const double* __restrict x, const double* __restrict y, const int* __restrict corners, size_t first,
                size_t end, double short2, double long2, double thinCosine, double* __restrict cosine,
                int* __restrict flags) {
  for (size_t t = first; t < end; ++t) {
    // Removed triangles (corners -1) read vertex 0: their slots are never asked for. (A value, not
    // std::max's reference, so that the loads stay plain gathers.)
    const int a = corners[3 * t] < 0 ? 0 : corners[3 * t];
    const int b = corners[3 * t + 1] < 0 ? 0 : corners[3 * t + 1];
    const int c = corners[3 * t + 2] < 0 ? 0 : corners[3 * t + 2];
    const Shape s = triangleShape(x[a], y[a], x[b], y[b], x[c], y[c], short2, long2, thinCosine);
    cosine[t] = s.cosine;
    flags[t] = s.flags;
  }
}

// The mask bits of the flags (all but the edge), set in every key until a key clears them.
constexpr int kEveryMask = 0x7fc;

// Folds one key into the combination over keys: the first key with the smallest cosine gives the
// worst angle and its edge, and the masks are and-ed.
void combineKey(const double* __restrict cosine, const int* __restrict flags, size_t first, size_t end,
                double* __restrict worst, int* __restrict combined) {
  for (size_t t = first; t < end; ++t) {
    const bool worse = cosine[t] < worst[t];
    const int edge = worse ? (flags[t] & 3) : (combined[t] & 3);
    worst[t] = worse ? cosine[t] : worst[t];
    combined[t] = (combined[t] & flags[t] & kEveryMask) | edge;
  }
}

}  // namespace

TriangleShapes::TriangleShapes(const ComeshMesh& mesh, const TriangleShapeBounds& bounds)
    : mesh_(mesh), thinCosine_(std::cos(bounds.thinAngle * kPi / 180)) {
  const int m = mesh.keyCount();
  for (int k = 0; k < m; ++k) {
    shortSquared_.push_back(bounds.shortLength.at(k) * bounds.shortLength.at(k));
    longSquared_.push_back(bounds.longLength.at(k) * bounds.longLength.at(k));
  }
  cosine_.resize(m);
  flags_.resize(m);
  stale_.assign(m, 1);
}

void TriangleShapes::keyMoved(int k) { stale_.at(k) = 1; }

void TriangleShapes::resize(size_t count) {
  corners_.resize(count, kUncomputed);
  worstCosine_.resize(count);
  combined_.resize(count);
  for (size_t k = 0; k < stale_.size(); ++k) {
    cosine_[k].resize(count);
    flags_[k].resize(count);
  }
}

void TriangleShapes::refresh() {
  const size_t count = mesh_.triangles.size();
  resize(count);
  bool moved = false;
  for (size_t k = 0; k < stale_.size(); ++k) {
    if (!stale_[k]) continue;
    // Every slot, also those whose corners changed: they are recomputed in every key when asked.
    computeKey(static_cast<int>(k), 0, count);
    stale_[k] = 0;
    moved = true;
  }
  if (moved) combineKeys(0, count);
  if (mesh_.topologyVersion != syncedVersion_) syncCorners();
  syncedVersion_ = mesh_.topologyVersion;
}

void TriangleShapes::syncCorners() {
  static_assert(sizeof(Triangle) == 3 * sizeof(int), "corners are compared as bytes");
  // Blocks of 64 triangles: memcmp is fast on long runs, and a change (a flip, a split, a
  // collapse: a few triangles) touches few blocks.
  constexpr size_t kBlock = 64;
  const size_t count = corners_.size();
  for (size_t first = 0; first < count; first += kBlock) {
    const size_t end = std::min(count, first + kBlock);
    if (std::memcmp(&corners_[first], &mesh_.triangles[first], (end - first) * sizeof(Triangle)) == 0) continue;
    for (size_t t = first; t < end; ++t) {
      const Triangle &cached = corners_[t], &now = mesh_.triangles[t];
      if (cached[0] != now[0] || cached[1] != now[1] || cached[2] != now[2]) recompute(static_cast<int>(t));
    }
  }
}

void TriangleShapes::recompute(int t) {
  for (size_t k = 0; k < stale_.size(); ++k) computeKey(static_cast<int>(k), t, t + 1);
  combineKeys(t, t + 1);
  corners_[t] = mesh_.triangles[t];
}

void TriangleShapes::combineKeys(size_t first, size_t end) {
  std::fill(worstCosine_.begin() + first, worstCosine_.begin() + end, 1.0);
  std::fill(combined_.begin() + first, combined_.begin() + end, kEveryMask);
  for (size_t k = 0; k < stale_.size(); ++k)
    combineKey(cosine_[k].data(), flags_[k].data(), first, end, worstCosine_.data(), combined_.data());
}

void TriangleShapes::computeKey(int k, size_t first, size_t end) {
  static_assert(sizeof(Triangle) == 3 * sizeof(int), "corners are read as one int array");
  shapeRange(mesh_.keys[k].col(0).data(), mesh_.keys[k].col(1).data(), mesh_.triangles.data()->data(), first, end,
             shortSquared_[k], longSquared_[k], thinCosine_, cosine_[k].data(), flags_[k].data());
}

}  // namespace ib
