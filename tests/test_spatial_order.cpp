#include "multimesh/spatial_order.h"
#include "meshing/multimesh_builder.h"
#include "scene/scene.h"
#include "testkit/example_scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <random>

using namespace ib;

namespace {

bool isPermutation(std::vector<int> order, size_t size) {
  std::sort(order.begin(), order.end());
  std::vector<int> expected(size);
  std::iota(expected.begin(), expected.end(), 0);
  return order == expected;
}

// Mean distance between points taken one after the other in `order`.
double meanStep(const std::vector<Eigen::Vector2d>& points, const std::vector<int>& order) {
  double sum = 0;
  for (size_t k = 1; k < order.size(); ++k) sum += (points[order[k]] - points[order[k - 1]]).norm();
  return sum / static_cast<double>(order.size() - 1);
}

}  // namespace

TEST_CASE("spatial order: the Hilbert order is a permutation whose consecutive points are near each other") {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> x(-50, 50), y(10, 70);
  std::vector<Eigen::Vector2d> points(2000);
  for (Eigen::Vector2d& p : points) p = {x(random), y(random)};
  const std::vector<int> order = hilbertOrder(points);
  REQUIRE(isPermutation(order, points.size()));
  std::vector<int> asGiven(points.size());
  std::iota(asGiven.begin(), asGiven.end(), 0);
  // Random points: about 42 px from one to the next as given, under 2 px along the curve (the
  // spacing of 2000 points over 100 x 60 px is about 1.7 px).
  INFO("as given " << meanStep(points, asGiven) << " px, along the curve " << meanStep(points, order) << " px");
  CHECK(meanStep(points, order) < 0.1 * meanStep(points, asGiven));
  // Degenerate inputs: none, and all in one place (kept in index order).
  CHECK(hilbertOrder({}).empty());
  const std::vector<int> same = hilbertOrder(std::vector<Eigen::Vector2d>(5, Eigen::Vector2d(3, 4)));
  CHECK(same == std::vector<int>{0, 1, 2, 3, 4});
}

TEST_CASE("spatial order: triangles are ordered by their smallest corner") {
  const std::vector<Triangle> triangles = {{5, 2, 9}, {0, 7, 3}, {4, 1, 8}, {2, 6, 3}, {9, 8, 1}};
  const std::vector<int> order = triangleOrder(triangles);
  REQUIRE(isPermutation(order, triangles.size()));
  const auto smallest = [&](int t) { return *std::min_element(triangles[t].begin(), triangles[t].end()); };
  for (size_t k = 1; k < order.size(); ++k) CHECK(smallest(order[k - 1]) <= smallest(order[k]));
}

TEST_CASE("spatial order: every bundled asset's multimesh joins vertices that are close in the numbering") {
  for (const std::string& file : test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    const BuiltScene built = buildMultimesh(loadScene(file), MultimeshBuildOptions{});
    const Multimesh& mesh = *built.multimesh;
    double gap = 0;
    long edges = 0;
    for (const Triangle& t : mesh.triangles())
      for (int c = 0; c < 3; ++c, ++edges) gap += std::abs(t[c] - t[(c + 1) % 3]);
    // A numbering in no spatial order puts the ends of an edge a third of the count apart on
    // average; along the curve they are a few percent apart (3-6% on these 300-600 vertex meshes).
    INFO(file << ": edges join vertices " << gap / edges << " apart on average, of " << mesh.vertexCount());
    CHECK(gap / edges < 0.1 * mesh.vertexCount());
  }
}
