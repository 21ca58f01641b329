#include "comesh/comesh_mesh.h"
#include "comesh/comesh_topology.h"
#include "testkit/shape_generators.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>

using namespace ib;

namespace {

// Smallest and largest angle (degrees) of triangle (p, q, r); 0 and 180 when it is not positive.
std::pair<double, double> angleRange(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
  if (!(signedArea(p, q, r) > 0)) return {0, 180};
  const Eigen::Vector2d c[3] = {p, q, r};
  double smallest = 180, largest = 0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d a = c[(i + 1) % 3] - c[i], b = c[(i + 2) % 3] - c[i];
    const double angle = std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0)) * 180 / M_PI;
    smallest = std::min(smallest, angle);
    largest = std::max(largest, angle);
  }
  return {smallest, largest};
}
double largestAngle(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) { return angleRange(p, q, r).second; }
double smallestAngle(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) { return angleRange(p, q, r).first; }

}  // namespace

TEST_CASE("comesh flips: a flip is made exactly when it lowers the largest angle of the pair over all keys and thins no key's smallest angle under both 5 degrees and its own (random quads, 1 to 3 keys)") {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> jitter(-0.45, 0.45);
  int flipped = 0, kept = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int m = 1 + trial % 3;
    // Quad a = 0, b = 1, c = 2, d = 3: triangles (a, b, c) and (b, a, d) share edge a -> b.
    Multimesh mesh(4, {{0, 1, 2}, {1, 0, 3}});
    double before = 0, after = 0;
    bool valid = true, thins = false;
    for (int k = 0; k < m; ++k) {
      Eigen::MatrixX2d x(4, 2);
      // Edge a b along x; c above it, d below, both moved about to make obtuse and acute pairs.
      x << 0, 0, 1 + jitter(rng), jitter(rng), 0.5 + jitter(rng), 0.15 + std::abs(jitter(rng)) * 1.5,
          0.5 + jitter(rng), -0.15 - std::abs(jitter(rng)) * 1.5;
      const auto p = [&](int v) -> Eigen::Vector2d { return x.row(v).transpose(); };
      valid = valid && signedArea(p(0), p(1), p(2)) > 0 && signedArea(p(1), p(0), p(3)) > 0;
      before = std::max({before, largestAngle(p(0), p(1), p(2)), largestAngle(p(1), p(0), p(3))});
      after = std::max({after, largestAngle(p(2), p(0), p(3)), largestAngle(p(3), p(1), p(2))});
      const double thinnest = std::min(smallestAngle(p(0), p(1), p(2)), smallestAngle(p(1), p(0), p(3)));
      thins = thins || std::min(smallestAngle(p(2), p(0), p(3)), smallestAngle(p(3), p(1), p(2))) < std::min(thinnest, 5.0);
      mesh.addKey(x, {}, {0, 1, 2, 3});
    }
    if (!valid || std::abs(after - before) < 1e-6) continue;  // not a multimesh, or too close to call
    ComeshMesh working(mesh, nullptr);
    working.fixed.assign(4, 0);  // the test is about the angle rule, not the boundary
    Remesher remesher(working, RemeshOptions{});
    RemeshCounts counts;
    const int flips = remesher.flipEdges(counts);
    CHECK(flips == (after < before && !thins ? 1 : 0));
    (flips ? flipped : kept) += 1;
  }
  // Both outcomes are exercised.
  CHECK(flipped >= 50);
  CHECK(kept >= 50);
}

TEST_CASE("comesh flips: a remesher that remembers refused flips flips exactly what a fresh one does, pass after pass, as keys move") {
  const GridMesh grid = rectangleGrid(12, 9, 3, 2);
  // Interior vertices moved by up to `amount` of the grid spacing: many obtuse triangles.
  const auto jitteredKey = [&](unsigned seed, double amount) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(-amount * 3 / 11, amount * 3 / 11);
    Eigen::MatrixX2d x = grid.points;
    for (int v = 0; v < x.rows(); ++v)
      if (std::find(grid.boundary.begin(), grid.boundary.end(), v) == grid.boundary.end())
        x.row(v) += Eigen::RowVector2d(jitter(rng), jitter(rng));
    return x;
  };
  const int m = 3;
  Multimesh mesh(static_cast<int>(grid.points.rows()), grid.triangles);
  for (int k = 0; k < m; ++k) mesh.addKey(jitteredKey(10 + k, 0.35), {}, grid.boundary);
  ComeshMesh working(mesh, nullptr);
  Remesher remesher(working, RemeshOptions{});
  int total = 0, changed = 0;
  for (int pass = 0; pass < 12; ++pass) {
    ComeshMesh copy = working;
    RemeshCounts counts;
    const int fresh = Remesher(copy, RemeshOptions{}).flipEdges(counts);
    const int remembered = remesher.flipEdges(counts);
    INFO("pass " << pass);
    CHECK(remembered == fresh);
    CHECK(working.triangles == copy.triangles);
    total += remembered;
    // One key moves (as a vertex step moves one key); every second pass, far enough to change
    // which flips its refusals allowed.
    const int k = pass % m;
    const Eigen::MatrixX2d before = working.keys[k];
    const Eigen::MatrixX2d target = jitteredKey(100 + pass, 0.35);
    working.keys[k] = before + (pass % 2 ? 0.02 : 0.5) * (target - before);
    remesher.keyMoved(k);
    changed += pass % 2 == 0;
  }
  // The passes did flip edges after the first (not only the first pass's clean-up).
  CHECK(total > 0);
  CHECK(changed > 0);
}
