// Mapping the keys for the editor's quick rebuilds: keys mapped side by side give the map one
// thread gives, and a build that starts from the previous build's map (meshing/previous_map.h)
// reproduces it when nothing changed, stays foldover-free after a feature moves, and is not used
// where it does not cover the new shape.
#include "core/thread_budget.h"
#include "meshing/multimesh_builder.h"
#include "meshing/previous_map.h"
#include "scene/scene.h"
#include "testkit/example_scenes.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>

#include <memory>

using namespace ib;

namespace {

std::shared_ptr<const Multimesh> build(const Scene& scene, const PreviousMap* previous = nullptr) {
  MultimeshBuildOptions options;
  options.previous = previous;
  return std::make_shared<const Multimesh>(*buildMultimesh(scene, options).multimesh);
}

PreviousMap sameKeys(const Scene& scene, std::shared_ptr<const Multimesh> mesh) {
  PreviousMap out;
  out.mesh = std::move(mesh);
  out.reference = scene.reference;
  for (size_t k = 0; k < scene.keys.size(); ++k) out.keyOf.push_back(static_cast<int>(k));
  return out;
}

double largestDifference(const Multimesh& a, const Multimesh& b, int key) {
  return (a.keyPositions(key) - b.keyPositions(key)).cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("multimesh builder: keys mapped side by side on two threads equal the map of one thread, bit for bit") {
  for (const std::string& file : ::test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    const Scene scene = loadScene(file);
    if (scene.keys.size() < 3) continue;  // with one key to untangle, the keys are not split
    INFO("asset " << file);
    std::shared_ptr<const Multimesh> one, two;
    {
      const ThreadLimit limit(1);
      one = build(scene);
    }
    {
      const ThreadLimit limit(2);
      two = build(scene);
    }
    REQUIRE(one->vertexCount() == two->vertexCount());
    for (int k = 0; k < one->keyCount(); ++k) CHECK(largestDifference(*one, *two, k) == 0);
  }
}

TEST_CASE("previous map: a build from the previous build's map of the same scene reproduces it within 1e-9 px") {
  for (const std::string& file : ::test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    INFO("asset " << file);
    const Scene scene = loadScene(file);
    const std::shared_ptr<const Multimesh> cold = build(scene);
    const PreviousMap previous = sameKeys(scene, cold);
    const std::shared_ptr<const Multimesh> warm = build(scene, &previous);
    REQUIRE(warm->vertexCount() == cold->vertexCount());
    for (int k = 0; k < cold->keyCount(); ++k) CHECK(largestDifference(*warm, *cold, k) < 1e-9);
  }
}

TEST_CASE("previous map: after a feature moves 3 px, the build from the previous map folds nothing and places the boundary as a fresh build") {
  int moved = 0;
  for (const std::string& file : ::test::bundledSceneFiles(INBETWEEN_ASSETS)) {
    const Scene before = loadScene(file);
    if (before.keys[static_cast<size_t>(before.reference)].features.empty()) continue;
    INFO("asset " << file);
    Scene after = before;
    // 3 px sideways: the builder snaps it back onto the outline, 0-3 px along it.
    after.keys[static_cast<size_t>(after.reference)].features.begin()->second += Eigen::Vector2d(3, 0);
    const PreviousMap previous = sameKeys(before, build(before));
    const std::shared_ptr<const Multimesh> fresh = build(after);
    const std::shared_ptr<const Multimesh> warm = build(after, &previous);
    REQUIRE(warm->vertexCount() == fresh->vertexCount());
    for (int k = 0; k < warm->keyCount(); ++k) {
      INFO("key " << after.keys[static_cast<size_t>(k)].name);
      CHECK(smallestTriangleArea(warm->triangles(), warm->keyPositions(k)).first > 0);
      double boundary = 0;
      for (int v = 0; v < warm->vertexCount(); ++v)
        if (warm->onBoundary()[static_cast<size_t>(v)])
          boundary = std::max(boundary, (warm->keyPositions(k).row(v) - fresh->keyPositions(k).row(v)).norm());
      CHECK(boundary < 1e-9);
    }
    ++moved;
  }
  CHECK(moved >= 10);
}

TEST_CASE("previous map: a map that does not cover the new shape is not used; the build is a fresh one") {
  const std::vector<std::string> files = ::test::bundledSceneFiles(INBETWEEN_ASSETS);
  const Scene scene = loadScene(files.front());
  // The previous map moved 1000 px away: no point of the new mesh is within reach of it.
  Multimesh shifted = *build(scene);
  for (int k = 0; k < shifted.keyCount(); ++k) {
    Eigen::MatrixX2d x = shifted.keyPositions(k);
    x.col(0).array() += 1000;
    shifted.setKeyPositions(k, x);
  }
  const PreviousMap previous = sameKeys(scene, std::make_shared<const Multimesh>(shifted));
  const int other = (scene.reference + 1) % static_cast<int>(scene.keys.size());
  const PreviousMapStart start(previous, shifted.keyPositions(scene.reference), 4);
  CHECK(start.covers(other));
  const PreviousMapStart away(previous, build(scene)->keyPositions(scene.reference), 4);
  CHECK_FALSE(away.covers(other));
  const std::shared_ptr<const Multimesh> fresh = build(scene), warm = build(scene, &previous);
  for (int k = 0; k < fresh->keyCount(); ++k) CHECK(largestDifference(*warm, *fresh, k) == 0);
}

TEST_CASE("previous map: a carried map's fold is untangled where it is; vertices more than kFoldRings rings away stay put") {
  const ib::test::Fixture f = ib::test::strip(600, 2);
  const Multimesh& mesh = f.mesh;
  const Eigen::MatrixX2d rest = mesh.keyPositions(0);
  Eigen::MatrixX2d carried = mesh.keyPositions(1);
  std::vector<char> locked = mesh.onBoundary();
  // Fold one interior vertex over a neighbour: push it across its ring.
  int moved = -1;
  for (int v = mesh.vertexCount() / 2; v < mesh.vertexCount(); ++v)
    if (!locked[static_cast<size_t>(v)]) {
      moved = v;
      break;
    }
  int neighbour = -1;
  for (const Edge& e : mesh.edges())
    if (e[0] == moved || e[1] == moved) neighbour = e[0] == moved ? e[1] : e[0];
  carried.row(moved) += 2.5 * (carried.row(neighbour) - carried.row(moved));
  REQUIRE(smallestTriangleArea(mesh.triangles(), carried).first <= 0);
  const std::vector<char> near = foldNeighbourhood(mesh.triangles(), carried, kFoldRings);
  Eigen::MatrixX2d x = carried;
  const UntangleResult r = untangleCarried(mesh.triangles(), rest, x, locked, UntangleOptions{});
  CHECK(r.injective);
  CHECK(smallestTriangleArea(mesh.triangles(), x).first > 0);
  double farthest = 0;
  int far = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (!near[static_cast<size_t>(v)]) farthest = std::max(farthest, (x.row(v) - carried.row(v)).norm()), ++far;
  CHECK(far > mesh.vertexCount() / 2);
  CHECK(farthest == 0);
}
