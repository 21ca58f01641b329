#include "comesh/comesh_block_energy.h"
#include "comesh/comesh_energy.h"
#include "multimesh/mesh_quality.h"
#include "testkit/shape_generators.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

using namespace ib;

namespace {

// A 6 x 4 grid on [0, 3] x [0, 2] with its interior vertices jittered (fixed seed): every
// triangle stays positive.
Eigen::MatrixX2d jittered(const GridMesh& grid, unsigned seed, double amount) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-amount, amount);
  Eigen::MatrixX2d x = grid.points;
  for (int v = 0; v < x.rows(); ++v)
    if (x(v, 0) > 1e-9 && x(v, 0) < 3 - 1e-9 && x(v, 1) > 1e-9 && x(v, 1) < 2 - 1e-9) x.row(v) += Eigen::RowVector2d(jitter(rng), jitter(rng));
  return x;
}

// Central differences of f at x, every coordinate.
template <typename F>
Eigen::MatrixX2d numericGradient(const F& f, Eigen::MatrixX2d x) {
  Eigen::MatrixX2d g(x.rows(), 2);
  const double h = 1e-6;
  for (int v = 0; v < x.rows(); ++v)
    for (int c = 0; c < 2; ++c) {
      const double keep = x(v, c);
      x(v, c) = keep + h;
      const double up = f(x);
      x(v, c) = keep - h;
      const double down = f(x);
      x(v, c) = keep;
      g(v, c) = (up - down) / (2 * h);
    }
  return g;
}

Eigen::MatrixX2d similarity(const Eigen::MatrixX2d& x, double angle, double scale, const Eigen::RowVector2d& shift) {
  Eigen::Matrix2d r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return (x * r.transpose() * scale).rowwise() + shift;
}

// Four differently distorted keys of `grid`, for the tests over 1 to 4 keys.
std::vector<Eigen::MatrixX2d> fourKeys(const GridMesh& grid) {
  return {jittered(grid, 7, 0.12), similarity(jittered(grid, 8, 0.12), 0.3, 1.7, {4, -1}), jittered(grid, 9, 0.12) * 0.8,
          similarity(jittered(grid, 10, 0.1), -1, 0.5, {0, 3})};
}

}  // namespace

TEST_CASE("comesh energy: ODT, MIPS and the block objective match central differences") {
  const GridMesh grid = rectangleGrid(6, 4, 3, 2);
  const Eigen::MatrixX2d a = jittered(grid, 7, 0.12), b = similarity(jittered(grid, 8, 0.12), 0.3, 1.7, {4, -1});
  const Eigen::MatrixX2d c = jittered(grid, 9, 0.12) * 0.8;
  const auto& t = grid.triangles;
  Eigen::MatrixX2d g = Eigen::MatrixX2d::Zero(a.rows(), 2);
  odtEnergy(t, a, &g);
  CHECK((g - numericGradient([&](const Eigen::MatrixX2d& x) { return odtEnergy(t, x, nullptr); }, a)).norm() <= 1e-6 * g.norm());
  Eigen::MatrixX2d gi = Eigen::MatrixX2d::Zero(a.rows(), 2), gj = gi;
  mipsEnergy(t, a, b, &gi, &gj);
  CHECK((gi - numericGradient([&](const Eigen::MatrixX2d& x) { return mipsEnergy(t, x, b, nullptr, nullptr); }, a)).norm() <=
        1e-6 * gi.norm());
  CHECK((gj - numericGradient([&](const Eigen::MatrixX2d& x) { return mipsEnergy(t, a, x, nullptr, nullptr); }, b)).norm() <=
        1e-6 * gj.norm());
  const std::vector<Eigen::MatrixX2d> keys = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    Eigen::MatrixX2d block;
    BlockEnergy energy;
    energy.prepare(t, keys, i, 1);
    energy.evaluate(keys[i], &block);
    const Eigen::MatrixX2d numeric =
        numericGradient([&](const Eigen::MatrixX2d& x) { return energy.evaluate(x, nullptr); }, keys[i]);
    CHECK((block - numeric).norm() <= 1e-6 * block.norm());
  }
}

TEST_CASE("comesh energy: eq. 8 minus key i's block energy does not depend on X_i, for 1 to 4 keys") {
  const GridMesh grid = rectangleGrid(6, 4, 3, 2);
  const std::vector<Eigen::MatrixX2d> all = fourKeys(grid);
  const std::vector<double> odtWeights = {0.7, 1.3, 0.4, 2.0};
  for (int m = 1; m <= 4; ++m) {
    std::vector<Eigen::MatrixX2d> keys(all.begin(), all.begin() + m);
    const std::vector<double> weights(odtWeights.begin(), odtWeights.begin() + m);
    for (int i = 0; i < m; ++i) {
      BlockEnergy block;
      block.prepare(grid.triangles, keys, i, weights[i]);
      const double rest = comeshEnergy(grid.triangles, keys, weights) - block.evaluate(keys[i], nullptr);
      std::vector<Eigen::MatrixX2d> moved = keys;
      moved[i] = similarity(jittered(grid, 20 + i, 0.1), 0.2, 1.1, {0.5, 0});
      const double movedRest = comeshEnergy(grid.triangles, moved, weights) - block.evaluate(moved[i], nullptr);
      CHECK(movedRest == Approx(rest).epsilon(1e-10).margin(1e-10 * comeshEnergy(grid.triangles, keys, weights)));
    }
  }
}

TEST_CASE("comesh energy: eq. 8 is the sum of its parts as odtEnergy, totalArea and mipsEnergy give them, for 1 to 4 keys") {
  const GridMesh grid = rectangleGrid(6, 4, 3, 2);
  const std::vector<Eigen::MatrixX2d> all = fourKeys(grid);
  const std::vector<double> odtWeights = {0.7, 1.3, 0.4, 2.0};
  // A deleted triangle (corners -1), as Comesh's working mesh holds until it compacts, counts nothing.
  std::vector<Triangle> withDeleted = grid.triangles;
  withDeleted.insert(withDeleted.begin() + 3, Triangle{-1, -1, -1});
  for (int m = 1; m <= 4; ++m) {
    const std::vector<Eigen::MatrixX2d> keys(all.begin(), all.begin() + m);
    const std::vector<double> weights(odtWeights.begin(), odtWeights.begin() + m);
    double expected = 0;
    for (int i = 0; i < m; ++i) {
      expected += weights[i] * odtEnergy(grid.triangles, keys[i], nullptr) / totalArea(grid.triangles, keys[i]);
      if (m > 1) expected += mipsEnergy(grid.triangles, keys[i], keys[(i + 1) % m], nullptr, nullptr);
    }
    INFO(m << " keys");
    CHECK(comeshEnergy(grid.triangles, keys, weights) == Approx(expected).epsilon(1e-12));
    CHECK(comeshEnergy(withDeleted, keys, weights) == Approx(expected).epsilon(1e-12));
    if (m == 1) continue;
    // A triangle turned over in any key makes some MIPS term, and so eq. 8, infinite.
    for (int k = 0; k < m; ++k) {
      std::vector<Eigen::MatrixX2d> turned = keys;
      const Triangle& t = grid.triangles[5];
      turned[k].row(t[0]) = turned[k].row(t[1]) + turned[k].row(t[2]) - turned[k].row(t[0]);  // across edge t1 t2
      CHECK(mipsEnergy(grid.triangles, turned[(k + m - 1) % m], turned[k], nullptr, nullptr) == std::numeric_limits<double>::infinity());
      CHECK(comeshEnergy(grid.triangles, turned, weights) == std::numeric_limits<double>::infinity());
    }
  }
}

TEST_CASE("comesh energy: after edge flips, updating the block energy gives what preparing it afresh gives") {
  const GridMesh grid = rectangleGrid(6, 4, 3, 2);
  const std::vector<Eigen::MatrixX2d> keys = {jittered(grid, 7, 0.05), similarity(jittered(grid, 8, 0.05), 0.3, 1.7, {4, -1}),
                                              jittered(grid, 9, 0.05) * 0.8};
  for (int i = 0; i < 3; ++i) {
    std::vector<Triangle> triangles = grid.triangles;
    BlockEnergy updated;
    updated.prepare(triangles, keys, i, 0.6);
    // Flip the shared edge of every other pair of triangles that form a convex quad in every key.
    int flips = 0;
    for (size_t t1 = 0; t1 < triangles.size(); t1 += 4)
      for (size_t t2 = t1 + 1; t2 < triangles.size() && t2 < t1 + 4; ++t2)
        for (int e = 0; e < 3; ++e) {
          const int a = triangles[t1][e], b = triangles[t1][(e + 1) % 3], c = triangles[t1][(e + 2) % 3];
          for (int f = 0; f < 3; ++f) {
            if (triangles[t2][f] != b || triangles[t2][(f + 1) % 3] != a) continue;
            const int d = triangles[t2][(f + 2) % 3];
            bool convex = true;
            for (const auto& x : keys)
              convex = convex && signedArea(x.row(c), x.row(a), x.row(d)) > 0 && signedArea(x.row(d), x.row(b), x.row(c)) > 0;
            if (!convex) continue;
            triangles[t1] = {c, a, d};
            triangles[t2] = {d, b, c};
            ++flips;
            e = 3;
            break;
          }
        }
    REQUIRE(flips >= 3);
    updated.update(triangles, keys);
    BlockEnergy fresh;
    fresh.prepare(triangles, keys, i, 0.6);
    Eigen::MatrixX2d g1, g2;
    const double e1 = updated.evaluate(keys[i], &g1), e2 = fresh.evaluate(keys[i], &g2);
    CHECK(e1 == Approx(e2).epsilon(1e-12));
    CHECK((g1 - g2).norm() <= 1e-12 * g2.norm());
  }
}

TEST_CASE("comesh energy: the prepared block energy is infinite when a triangle is inverted in the key or a neighbour") {
  const GridMesh grid = rectangleGrid(6, 4, 3, 2);
  std::vector<Eigen::MatrixX2d> keys = {jittered(grid, 7, 0.12), jittered(grid, 8, 0.12)};
  BlockEnergy block;
  block.prepare(grid.triangles, keys, 0, 1);
  Eigen::MatrixX2d folded = keys[0];
  const Triangle& t = grid.triangles[5];
  folded.row(t[0]) = 2 * (0.5 * (folded.row(t[1]) + folded.row(t[2]))) - folded.row(t[0]);  // across the far edge
  CHECK(std::isinf(block.evaluate(folded, nullptr)));
  keys[1] = folded;
  block.prepare(grid.triangles, keys, 0, 1);
  CHECK(std::isinf(block.evaluate(keys[0], nullptr)));
}

TEST_CASE("comesh energy: MIPS of a similarity map is 2 per unit area, and larger for any shear") {
  const GridMesh grid = rectangleGrid(6, 4, 3, 2);
  const Eigen::MatrixX2d a = jittered(grid, 3, 0.1);
  const double area = totalArea(grid.triangles, a);
  CHECK(mipsEnergy(grid.triangles, a, a, nullptr, nullptr) == Approx(2 * area).epsilon(1e-12));
  CHECK(mipsEnergy(grid.triangles, a, similarity(a, 1.1, 3.5, {2, 2}), nullptr, nullptr) == Approx(2 * area).epsilon(1e-12));
  Eigen::MatrixX2d sheared = a;
  sheared.col(0) += 0.4 * a.col(1);
  CHECK(mipsEnergy(grid.triangles, a, sheared, nullptr, nullptr) > 2 * area * 1.01);
}

TEST_CASE("comesh energy: ODT prefers the Delaunay diagonal of a rhombus") {
  // Rhombus with a short horizontal diagonal (1) and a long vertical one (3).
  Eigen::MatrixX2d x(4, 2);
  x << -0.5, 0, 0, -1.5, 0.5, 0, 0, 1.5;
  const std::vector<Triangle> shortDiagonal = {{0, 1, 2}, {0, 2, 3}}, longDiagonal = {{0, 1, 3}, {1, 2, 3}};
  CHECK(odtEnergy(shortDiagonal, x, nullptr) < odtEnergy(longDiagonal, x, nullptr));
}

TEST_CASE("mesh quality: a right-triangle grid has 45 degree angles and identical keys map conformally") {
  const GridMesh grid = rectangleGrid(6, 4, 5, 3);  // unit squares
  Multimesh mesh(static_cast<int>(grid.points.rows()), grid.triangles);
  mesh.addKey(grid.points, {}, {});
  mesh.addKey(similarity(grid.points, 0.5, 2, {1, 1}), {}, {});
  const MultimeshQuality q = measureQuality(mesh);
  REQUIRE(q.keys.size() == 2);
  REQUIRE(q.maps.size() == 2);
  CHECK(q.keys[0].smallestAngle == Approx(45).epsilon(1e-9));
  CHECK(q.keys[0].meanSmallestAngle == Approx(45).epsilon(1e-9));
  CHECK(q.keys[0].shareUnder20 == 0);
  CHECK(q.maps[0].mipsMean == Approx(2).epsilon(1e-9));
  CHECK(q.maps[1].mipsMax == Approx(2).epsilon(1e-9));
}
