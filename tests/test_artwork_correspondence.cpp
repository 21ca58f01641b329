// "correspondence": "artwork" (meshing/outline_matching.h, meshing/artwork_agreement.h) on the
// drawn test scenes of tests/correspondence: what is the same in every drawing stays where the
// reference key has it, and a scene it cannot map is built by arc length instead, with a note.
#include "meshing/artwork_agreement.h"
#include "meshing/multimesh_builder.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

using namespace ib;

namespace {

std::vector<Eigen::Vector2d> referencePoints(const Multimesh& mesh, int reference) {
  std::vector<Eigen::Vector2d> out;
  for (int v = 0; v < mesh.vertexCount(); ++v) out.push_back(mesh.keyPositions(reference).row(v).transpose());
  return out;
}

Scene correspondenceScene(const std::string& name, OutlineCorrespondence correspondence) {
  Scene scene = loadScene((std::filesystem::path(INBETWEEN_SOURCE_DIR) / "tests" / "correspondence" / name / "scene.json").string());
  scene.correspondence = correspondence;
  return scene;
}

}  // namespace

TEST_CASE("correspondence artwork: on cat-tail the artwork's anchors are where the reference key has them in every key, "
          "and every vertex where the drawings agree around it stays within a pixel") {
  const Scene scene = correspondenceScene("cat-tail", OutlineCorrespondence::kArtwork);
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  REQUIRE(built.fallback.empty());
  const Multimesh& mesh = *built.multimesh;
  std::vector<RgbaImage> drawings;
  for (const KeySpec& key : scene.keys) drawings.push_back(readPng(key.drawing));
  const int reference = scene.reference;
  const auto farthest = [&](const Multimesh& m, int v) {  // from the reference key's place, over the keys (px)
    double far = 0;
    for (int k = 0; k < m.keyCount(); ++k)
      far = std::max(far, (m.keyPositions(k).row(v) - m.keyPositions(reference).row(v)).norm());
    return far;
  };
  // The anchors are exactly where the reference key has them, in the initial map of every key.
  const std::vector<int> anchors = artworkAnchors(drawings, built.edgeLength, referencePoints(mesh, reference),
                                                  mesh.triangles(), mesh.onBoundary(), std::vector<char>(mesh.vertexCount(), 0));
  CHECK(anchors.size() > 100);
  double worstAnchor = 0;
  for (int v : anchors) worstAnchor = std::max(worstAnchor, farthest(mesh, v));
  CHECK(worstAnchor < 1e-9);
  // Every vertex, inside or on the outline, where the drawings agree over three edge lengths
  // around it stays within a pixel; arc length alone puts some tens of pixels off.
  AgreementOptions deep;
  deep.margin = static_cast<int>(std::ceil(3 * built.edgeLength));
  deep.opaqueOnly = true;
  const AgreementMask same = agreement(drawings, deep);
  int inside = 0;
  double worst = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (same.at(mesh.keyPositions(reference).row(v).transpose())) worst = std::max(worst, farthest(mesh, v)), ++inside;
  CHECK(inside > 200);
  CHECK(worst < 1.0);

  const BuiltScene byArcLength = buildMultimesh(correspondenceScene("cat-tail", OutlineCorrespondence::kOutline), MultimeshBuildOptions{});
  double worstOutline = 0;
  for (int v = 0; v < byArcLength.multimesh->vertexCount(); ++v)
    if (same.at(byArcLength.multimesh->keyPositions(reference).row(v).transpose()))
      worstOutline = std::max(worstOutline, farthest(*byArcLength.multimesh, v));
  CHECK(worstOutline > 5);
}

TEST_CASE("correspondence artwork: a scene it cannot map without folds is built by arc length, and says so") {
  const BuiltScene built = buildMultimesh(correspondenceScene("chick-squash", OutlineCorrespondence::kArtwork), MultimeshBuildOptions{});
  REQUIRE(built.multimesh);
  CHECK(built.fallback.find("correspondence \"artwork\" folded key") != std::string::npos);
  CHECK(built.fallback.find("\"outline\"") != std::string::npos);
}
