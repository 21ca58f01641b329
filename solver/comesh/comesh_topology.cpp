#include "comesh/comesh_topology.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace ib {

namespace {

// The smallest and largest angle of some triangles, as cosines (a cosine falls as its angle grows).
struct AngleRange {
  double smallest = -1;  // cosine of the smallest angle: the largest cosine seen
  double largest = 1;    // cosine of the largest angle: the smallest cosine seen
  void add(const AngleRange& other) {
    smallest = std::max(smallest, other.smallest);
    largest = std::min(largest, other.largest);
  }
  bool degenerate() const { return smallest >= 1; }
};

// Angles of triangle (p0, p1, p2); a triangle that is not positive counts as angles 0 and 180.
AngleRange angles(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2) {
  if (!(signedArea(p0, p1, p2) > 0)) return {1, -1};
  const Eigen::Vector2d e[3] = {p1 - p0, p2 - p1, p0 - p2};
  AngleRange range;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d& to = e[i];
    const Eigen::Vector2d from = -e[(i + 2) % 3];
    const double c = from.dot(to) / std::sqrt(from.squaredNorm() * to.squaredNorm());
    range.add({c, c});
  }
  return range;
}

// Cosine of the largest angle of triangle (p0, p1, p2), or -1 (180 degrees) when it is not positive.
double largestAngleCosine(const double* x, const double* y, int p0, int p1, int p2) {
  const double ax = x[p1] - x[p0], ay = y[p1] - y[p0], bx = x[p2] - x[p0], by = y[p2] - y[p0];
  if (!(ax * by - ay * bx > 0)) return -1;
  const double cx = bx - ax, cy = by - ay;
  int edge;  // edges 01, 12, 20
  return ib::largestAngleCosine(ax * ax + ay * ay, cx * cx + cy * cy, bx * bx + by * by, edge);
}

class Timer {
 public:
  explicit Timer(double& seconds) : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
  ~Timer() { seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  double& seconds_;
  std::chrono::steady_clock::time_point start_;
};

// Angles of `corners` (triangles given by vertex indices) over every key, with vertex `moved`
// placed at `position[k]` instead of its own position (moved = -1: none).
AngleRange keyAngles(const ComeshMesh& mesh, const std::vector<Triangle>& corners, int moved,
                            const std::vector<Eigen::Vector2d>& position) {
  AngleRange range;
  for (int k = 0; k < mesh.keyCount(); ++k) {
    auto at = [&](int v) -> Eigen::Vector2d {
      return v == moved ? position[k] : Eigen::Vector2d(mesh.keys[k].row(v).transpose());
    };
    for (const Triangle& t : corners) range.add(angles(at(t[0]), at(t[1]), at(t[2])));
  }
  return range;
}

// Whether triangles `after`, replacing `before`, have in some key a smallest angle under both
// that key's smallest before and the angle whose cosine is `floorCosine`: an operation judged by
// the angles over all keys could otherwise thin one key down to another key's worst triangle.
bool thinsSomeKey(const ComeshMesh& mesh, const std::vector<Triangle>& before, const std::vector<Triangle>& after,
                  double floorCosine) {
  for (int k = 0; k < mesh.keyCount(); ++k) {
    const auto smallest = [&](const std::vector<Triangle>& corners) {
      AngleRange range;
      const Eigen::MatrixX2d& x = mesh.keys[k];
      for (const Triangle& t : corners)
        range.add(angles(x.row(t[0]).transpose(), x.row(t[1]).transpose(), x.row(t[2]).transpose()));
      return range.smallest;  // a cosine: larger is thinner
    };
    if (smallest(after) > std::max(smallest(before), floorCosine)) return true;
  }
  return false;
}

std::vector<int> neighbours(const ComeshMesh& mesh, int v) {
  std::vector<int> out;
  for (int t : mesh.around[v])
    for (int w : mesh.triangles[t])
      if (w != v) out.push_back(w);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool connected(const ComeshMesh& mesh, int a, int b) {
  for (int t : mesh.around[a])
    for (int w : mesh.triangles[t])
      if (w == b) return true;
  return false;
}

// The triangles of edge (a, b) before, and after a vertex v splits it, as corner lists.
void splitTriangles(const ComeshMesh& mesh, int a, int b, int v, std::vector<Triangle>& before,
                    std::vector<Triangle>& after) {
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, a}}) {
    const int t = mesh.triangleWith(p, q);
    if (t < 0) continue;
    const int c = mesh.thirdCorner(t, p, q);
    before.push_back({p, q, c});
    after.push_back({p, v, c});
    after.push_back({v, q, c});
  }
}

// Every key's mean edge length (px): the unit of the relative bounds.
std::vector<double> meanEdgeLengths(const ComeshMesh& mesh) {
  std::vector<double> unit;
  for (int k = 0; k < mesh.keyCount(); ++k) {
    double sum = 0;
    for (const Triangle& t : mesh.triangles)
      for (int i = 0; i < 3; ++i) sum += (mesh.keys[k].row(t[i]) - mesh.keys[k].row(t[(i + 1) % 3])).norm();
    unit.push_back(sum / std::max<size_t>(3 * mesh.triangles.size(), 1));
  }
  return unit;
}

TriangleShapeBounds shapeBounds(const std::vector<double>& unit, const RemeshOptions& options) {
  TriangleShapeBounds bounds;
  for (double u : unit) {
    bounds.shortLength.push_back(options.collapseLength * u);
    bounds.longLength.push_back(options.splitLength * u);
  }
  bounds.thinAngle = options.collapseAngle;
  return bounds;
}

}  // namespace

Remesher::Remesher(ComeshMesh& mesh, const RemeshOptions& options)
    : mesh_(mesh),
      options_(options),
      cosCollapse_(std::cos(options.collapseAngle * 3.14159265358979323846 / 180)),
      cosFlipFloor_(std::cos(5 * 3.14159265358979323846 / 180)),
      unit_(meanEdgeLengths(mesh)),
      shapes_(mesh, shapeBounds(unit_, options)),
      moves_(mesh.keyCount(), 0) {}

double Remesher::relativeLength(int k, int a, int b) const {
  return (mesh_.keys[k].row(a) - mesh_.keys[k].row(b)).norm() / unit_[k];
}

double Remesher::chordDeviation(int k, int a, int b, int c) const {
  if (!mesh_.chordDeviation) return 0;
  const int arc = mesh_.arc[a];
  // A vertex past a's arc is its end (the next arc's start, at u = 0 of that arc).
  const auto along = [&](int v) { return (mesh_.arc[v] == arc && mesh_.u(v, k) > 0) ? mesh_.u(v, k) : 1.0; };
  return mesh_.chordDeviation(k, arc, mesh_.u(a, k), along(b), along(c));
}

void Remesher::keyMoved(int k) {
  shapes_.keyMoved(k);
  ++moves_[k];
}

void Remesher::refreshCaches() {
  shapes_.refresh();
  refusals_.resize(mesh_.triangles.size());
  twin_.resize(mesh_.triangles.size(), -1);
}

Remesher::WorstAngle Remesher::worstAngle(int t) const {
  return {shapes_.worstCosine(t), shapes_.worstEdge(t)};
}

bool Remesher::flipImproves(int a, int b, int c, int d, double before, Refusal& refusal) const {
  const int m = mesh_.keyCount();
  // Every key must improve; the key that refused this triangle's flip last time is asked first,
  // as it usually refuses again (the answer does not depend on the order).
  for (int j = 0; j < m; ++j) {
    const int k = (refusal.key + j) % m;
    const double* x = mesh_.keys[k].col(0).data();
    const double* y = mesh_.keys[k].col(1).data();
    const double after = std::min(largestAngleCosine(x, y, c, a, d), largestAngleCosine(x, y, d, b, c));
    if (!(after > before + kFlipGain)) {
      refusal = {k, a, b, c, d, after, moves_[k]};
      return false;
    }
  }
  return true;
}

int Remesher::twinOf(int t, int a, int b) {
  const int cached = twin_[t];
  if (cached >= 0 && cached < static_cast<int>(mesh_.triangles.size())) {
    const Triangle& c = mesh_.triangles[cached];
    for (int i = 0; i < 3; ++i)
      if (c[i] == b && c[(i + 1) % 3] == a) return cached;
  }
  return twin_[t] = mesh_.triangleWith(b, a);
}

int Remesher::flipEdges(RemeshCounts& counts) {
  Timer timer(counts.flipSeconds);
  int flips = 0;
  refreshCaches();
  for (size_t t = 0; t < mesh_.triangles.size(); ++t) {
    // A flip keeps the whole angles at the edge's ends, so it can only lower the largest angle of
    // the pair (over all keys) when that angle faces the edge: the only candidate of a triangle is
    // its longest edge in the key where its largest angle is largest. (The twin's candidate is
    // tried when the twin's turn comes.)
    const Triangle tri = mesh_.triangles[t];
    if (tri[0] < 0) continue;
    const WorstAngle worst = worstAngle(static_cast<int>(t));
    // The new triangles' angles at a and b are sums of the old ones, which add up to 360 degrees
    // minus the two angles facing the edge: one of them is at least 180 minus the largest angle.
    // So no flip helps unless the largest angle is obtuse, and if it is only the twin's, the
    // twin's turn tries the same edge.
    if (worst.cosine >= 0) continue;
    const int a = tri[worst.edge], b = tri[(worst.edge + 1) % 3];
    const int twin = twinOf(static_cast<int>(t), a, b);
    if (twin < 0) continue;  // boundary (and so every cohesive) edge
    const int c = tri[(worst.edge + 2) % 3], d = mesh_.thirdCorner(twin, b, a);
    if (c == d || (mesh_.onBoundary(c) && mesh_.onBoundary(d))) continue;
    const double before = std::min(worst.cosine, worstAngle(twin).cosine);
    Refusal& refusal = refusals_[t];
    if (refusal.stands(a, b, c, d, before, moves_) || !flipImproves(a, b, c, d, before, refusal) ||
        connected(mesh_, c, d))
      continue;
    // The quad a, d, b, c (counterclockwise) gets the diagonal c-d: no key may thin there under
    // both 5 degrees and what it had (10, as for collapses, kept Comesh from lowering
    // pentagon-star-thin's largest MIPS distortion at all).
    if (thinsSomeKey(mesh_, {{a, b, c}, {b, a, d}}, {{a, d, c}, {d, b, c}}, cosFlipFloor_)) continue;
    mesh_.flip(a, b);
    refreshCaches();  // triangles t and twin changed; the twin may come later in this pass
    ++flips;
  }
  counts.flips += flips;
  return flips;
}

std::vector<Eigen::Vector2d> Remesher::boundaryMidpoint(int a, int b, Eigen::RowVectorXd& u) const {
  const int m = mesh_.keyCount(), arc = mesh_.arc[a];
  u.resize(m);
  std::vector<Eigen::Vector2d> position(m);
  for (int k = 0; k < m; ++k) {
    const double end = (mesh_.arc[b] == arc && mesh_.u(b, k) > 0) ? mesh_.u(b, k) : 1.0;
    u[k] = 0.5 * (mesh_.u(a, k) + end);
    position[k] = mesh_.closedIn[arc][k] ? Eigen::Vector2d(0.5 * (mesh_.keys[k].row(a) + mesh_.keys[k].row(b)).transpose())
                                         : mesh_.point(k, arc, u[k]);
  }
  return position;
}

int Remesher::splitEdges(RemeshCounts& counts) {
  Timer timer(counts.splitSeconds);
  int splits = 0;
  refreshCaches();
  const size_t count = mesh_.triangles.size();
  for (size_t t = 0; t < count; ++t) {
    if (mesh_.triangles[t][0] < 0) continue;
    int candidates = edgeCandidates(static_cast<int>(t), false);
    for (int i = 0; i < 3 && candidates; ++i) {
      const Triangle tri = mesh_.triangles[t];
      if (!(candidates & (1 << i))) continue;
      const int a = tri[i], b = tri[(i + 1) % 3];
      if (a > b && mesh_.triangleWith(b, a) >= 0) continue;  // inside edges once
      if (!trySplit(a, b)) continue;
      refreshCaches();
      ++splits;  // triangle t changed: its remaining edges as they are now
      candidates = edgeCandidates(static_cast<int>(t), false);
    }
  }
  counts.splits += splits;
  return splits;
}

bool Remesher::trySplit(int a, int b) {
  const int m = mesh_.keyCount(), v = mesh_.vertexCount();
  const bool boundary = mesh_.triangleWith(a, b) < 0 || mesh_.triangleWith(b, a) < 0;
  std::vector<Eigen::Vector2d> position(m);
  Eigen::RowVectorXd u = Eigen::RowVectorXd::Zero(m);
  if (boundary) {
    if (!mesh_.point) return false;
    if (mesh_.next[b] == a) std::swap(a, b);
    if (mesh_.next[a] != b) return false;
    position = boundaryMidpoint(a, b, u);
  } else {
    for (int k = 0; k < m; ++k) position[k] = 0.5 * (mesh_.keys[k].row(a) + mesh_.keys[k].row(b)).transpose();
  }
  std::vector<Triangle> before, after;
  splitTriangles(mesh_, a, b, v, before, after);
  for (const Triangle& t : before)
    if (boundary && mesh_.onBoundary(t[2])) return false;
  const std::vector<Eigen::Vector2d> none;
  const AngleRange old = keyAngles(mesh_, before, -1, none), fresh = keyAngles(mesh_, after, v, position);
  if (fresh.smallest > cosCollapse_ || fresh.largest < old.largest) return false;
  // A cut side splits with its partner, the new vertices collocated where the cut is closed.
  const std::array<int, 2> partner = boundary ? mesh_.cutPartner(a, b) : std::array<int, 2>{-1, -1};
  std::vector<Eigen::Vector2d> partnerPosition;
  Eigen::RowVectorXd partnerU;
  if (partner[0] >= 0) {
    const bool reversed = mesh_.next[partner[1]] == partner[0];
    if (!reversed && mesh_.next[partner[0]] != partner[1]) return false;
    partnerPosition = reversed ? boundaryMidpoint(partner[1], partner[0], partnerU)
                               : boundaryMidpoint(partner[0], partner[1], partnerU);
    for (int k = 0; k < m; ++k)
      if (mesh_.closedIn[mesh_.arc[a]][k]) partnerPosition[k] = position[k];
    std::vector<Triangle> pb, pa;
    splitTriangles(mesh_, partner[0], partner[1], v, pb, pa);
    if (mesh_.onBoundary(pb.at(0)[2])) return false;
    const AngleRange po = keyAngles(mesh_, pb, -1, none), pf = keyAngles(mesh_, pa, v, partnerPosition);
    if (pf.smallest > cosCollapse_ || pf.largest < po.largest) return false;
  }
  auto insert = [&](int p, int q, const std::vector<Eigen::Vector2d>& at, const Eigen::RowVectorXd& params) {
    const int w = mesh_.addVertex(at);
    if (boundary) {
      mesh_.arc[w] = mesh_.arc[p];
      mesh_.u.row(w) = params;
      for (int k = 0; k < m; ++k) mesh_.outline[k][w] = !mesh_.closedIn[mesh_.arc[p]][k];
    }
    mesh_.split(p, q, w);
    return w;
  };
  insert(a, b, position, u);
  if (partner[0] >= 0) {
    const int w = insert(partner[0], partner[1], partnerPosition, partnerU);
    mesh_.splitPairs(a, b, v, partner[0], partner[1], w);
  }
  return true;
}

int Remesher::edgeCandidates(int t, bool collapse) const {
  return collapse ? (shapes_.shortInEveryKey(t) | shapes_.thinInEveryKey(t)) : shapes_.longInEveryKey(t);
}

int Remesher::collapseEdges(RemeshCounts& counts) {
  Timer timer(counts.collapseSeconds);
  int collapses = 0;
  refreshCaches();
  for (size_t t = 0; t < mesh_.triangles.size(); ++t) {
    if (mesh_.triangles[t][0] < 0) continue;
    int candidates = edgeCandidates(static_cast<int>(t), true);
    for (int i = 0; i < 3 && candidates; ++i) {
      const Triangle tri = mesh_.triangles[t];
      if (!(candidates & (1 << i))) continue;
      if (!tryCollapse(tri[i], tri[(i + 1) % 3]) && !tryCollapse(tri[(i + 1) % 3], tri[i])) continue;
      refreshCaches();
      ++collapses;  // triangle t changed or went away: its remaining edges as they are now
      candidates = mesh_.triangles[t][0] < 0 ? 0 : edgeCandidates(static_cast<int>(t), true);
    }
  }
  if (collapses > 0) mesh_.compact();
  counts.collapses += collapses;
  return collapses;
}

bool Remesher::collapsible(int from, int to) const {
  if (mesh_.fixed[from]) return false;
  if (!mesh_.onBoundary(from)) return mesh_.triangleWith(from, to) >= 0 && mesh_.triangleWith(to, from) >= 0;
  // A boundary vertex may only merge into a walk neighbour, when it slides in every key (no
  // feature, no cut side) and its loop keeps at least three vertices.
  if (mesh_.next[from] != to && mesh_.previous[from] != to) return false;
  for (int k = 0; k < mesh_.keyCount(); ++k)
    if (!mesh_.slides(from, k)) return false;
  return mesh_.next[mesh_.next[mesh_.next[from]]] != from;
}

bool Remesher::tryCollapse(int from, int to) {
  if (!collapsible(from, to)) return false;
  // Link condition: the ends share exactly the edge's opposite corners (two inside, one on the boundary).
  const std::vector<int> ring = neighbours(mesh_, from), other = neighbours(mesh_, to);
  std::vector<int> shared;
  std::set_intersection(ring.begin(), ring.end(), other.begin(), other.end(), std::back_inserter(shared));
  if (shared.size() != (mesh_.onBoundary(from) ? 1u : 2u)) return false;
  const int walk = mesh_.next[from] == to ? mesh_.previous[from] : mesh_.next[from];  // -1 inside
  if (walk >= 0) {  // the merged boundary edge follows the outline as well as the two it replaces
    const int first = mesh_.previous[from], last = mesh_.next[from];
    for (int k = 0; k < mesh_.keyCount(); ++k) {
      const double allowed = std::max(std::min(options_.chordTolerance * unit_[k], options_.outlineTolerance), chordDeviation(k, first, from, last));
      if (chordDeviation(k, first, last, last) > allowed) return false;
    }
  }
  std::vector<Triangle> before, after;
  for (int t : mesh_.around[from]) {
    Triangle c = mesh_.triangles[t];
    before.push_back(c);
    if (std::find(c.begin(), c.end(), to) != c.end()) continue;
    std::replace(c.begin(), c.end(), from, to);
    after.push_back(c);
  }
  for (int n : ring) {
    if (n == to) continue;
    if (n != walk && mesh_.onBoundary(to) && mesh_.onBoundary(n) && !connected(mesh_, to, n)) return false;
    bool longEverywhere = true;
    for (int k = 0; k < mesh_.keyCount() && longEverywhere; ++k)
      longEverywhere = relativeLength(k, to, n) > options_.splitLength;
    if (longEverywhere) return false;
  }
  const std::vector<Eigen::Vector2d> none;
  const AngleRange old = keyAngles(mesh_, before, -1, none), fresh = keyAngles(mesh_, after, -1, none);
  if (fresh.degenerate() || fresh.smallest > old.smallest) return false;
  if (thinsSomeKey(mesh_, before, after, cosCollapse_)) return false;
  mesh_.collapse(from, to);
  return true;
}

}  // namespace ib
