// "correspondence": "artwork" (meshing/outline_matching.h, meshing/artwork_agreement.h) on the
// drawn test scenes of tests/correspondence: what is the same in every drawing stays where the
// reference key has it, the placement keeps it there, and a scene it cannot map is built with the
// settings that hold it less, with a note.
#include "animation/frame_changes.h"
#include "interpolation/interpolator.h"
#include "meshing/artwork_agreement.h"
#include "meshing/artwork_regions.h"
#include "meshing/multimesh_builder.h"
#include "pipeline/scene_frames.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

using namespace ib;

namespace {

std::vector<Eigen::Vector2d> referencePoints(const Multimesh& mesh, int reference) {
  std::vector<Eigen::Vector2d> out;
  for (int v = 0; v < mesh.vertexCount(); ++v) out.push_back(mesh.keyPositions(reference).row(v).transpose());
  return out;
}

// The farthest vertex v is in any key from its place in the reference key (px).
double farthestFromReference(const Multimesh& mesh, int reference, int v) {
  double far = 0;
  for (int k = 0; k < mesh.keyCount(); ++k)
    far = std::max(far, (mesh.keyPositions(k).row(v) - mesh.keyPositions(reference).row(v)).norm());
  return far;
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
  const auto farthest = [&](const Multimesh& m, int v) { return farthestFromReference(m, reference, v); };
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

TEST_CASE("correspondence artwork: chick-squash's eye and stripe, which move with the squash, are pinned at their "
          "centroids in every key (within a pixel of where they were drawn); the cat, whose detail did not move, gets none") {
  const Scene chick = correspondenceScene("chick-squash", OutlineCorrespondence::kArtwork);
  std::vector<RgbaImage> drawings;
  for (const KeySpec& key : chick.keys) drawings.push_back(readPng(key.drawing));
  const std::vector<std::vector<Eigen::Vector2d>> pins = ArtworkRegions(drawings, chick.reference).pins(3.0);
  REQUIRE(pins.size() == 3);
  REQUIRE(pins[0].size() == 2);
  // tests/correspondence/draw.py: the body an ellipse (48, 87 - ry) with radii (rx, ry), the eye a
  // disc at (cx + 0.45 rx, cy - 0.35 ry), the stripe the band cy + 0.10 ry .. cy + 0.30 ry.
  const std::map<std::string, Eigen::Vector2d> radii{{"stand", {26, 30}}, {"squash", {34, 23}}, {"stretch", {21, 37}}};
  for (size_t k = 0; k < 3; ++k) {
    INFO("key " << chick.keys[k].name);
    const Eigen::Vector2d r = radii.at(chick.keys[k].name), c(48, 87 - r.y());
    CHECK((pins[k][0] - Eigen::Vector2d(c.x() + 0.45 * r.x(), c.y() - 0.35 * r.y())).norm() < 1.0);
    CHECK((pins[k][1] - Eigen::Vector2d(c.x(), c.y() + 0.2 * r.y())).norm() < 1.0);
  }
  const Scene cat = correspondenceScene("cat-tail", OutlineCorrespondence::kArtwork);
  std::vector<RgbaImage> catDrawings;
  for (const KeySpec& key : cat.keys) catDrawings.push_back(readPng(key.drawing));
  CHECK(ArtworkRegions(catDrawings, cat.reference).pins(12.0)[0].empty());
}

TEST_CASE("correspondence artwork: chick-squash builds at its first edge length without a note under either "
          "correspondence (its squash matched as drawn: test_squash_correspondence.cpp)") {
  for (const OutlineCorrespondence correspondence : {OutlineCorrespondence::kArtwork, OutlineCorrespondence::kOutline}) {
    const BuiltScene built = buildMultimesh(correspondenceScene("chick-squash", correspondence), MultimeshBuildOptions{});
    REQUIRE(built.multimesh);
    CHECK(built.fallback.empty());
    CHECK(built.failedAttempts.empty());
    CHECK(built.attempts == 1);
  }
}

namespace {

// Per vertex of `still`, the largest distance (px) from where the reference key has it over the
// frames of the scene on `mesh`; sorted.
std::vector<double> stillDrift(const Scene& scene, const Multimesh& mesh, const std::vector<int>& still) {
  FrameStream stream = sceneFrameStream(scene, mesh);
  std::vector<double> drift(still.size(), 0);
  while (!stream.done()) {
    const AnimationFrame frame = stream.next();
    for (size_t i = 0; i < still.size(); ++i)
      drift[i] = std::max(drift[i], (frame.x.row(still[i]) - mesh.keyPositions(scene.reference).row(still[i])).norm());
  }
  std::sort(drift.begin(), drift.end());
  return drift;
}

double quantile(const std::vector<double>& sorted, double q) { return sorted[static_cast<size_t>(q * (sorted.size() - 1))]; }

}  // namespace

TEST_CASE("correspondence artwork: the cat's body, drawn the same in every key, stays where it was drawn in every "
          "frame while the tail swings (median within 0.05 px, 99% within 0.25 px); placed by the blend it drifts") {
  const Scene scene = correspondenceScene("cat-tail", OutlineCorrespondence::kArtwork);
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  REQUIRE(built.fallback.empty());
  const Multimesh& mesh = *built.multimesh;
  // The vertices every key has within a tenth of a pixel of the reference key's place.
  std::vector<int> still;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (farthestFromReference(mesh, scene.reference, v) < 0.1) still.push_back(v);
  REQUIRE(still.size() > static_cast<size_t>(mesh.vertexCount() / 3));
  const std::vector<double> byStillness = stillDrift(scene, mesh, still);
  CHECK(quantile(byStillness, 0.5) < 0.05);  // measured 0.02
  CHECK(quantile(byStillness, 0.99) < 0.25);  // 0.15; the worst, 0.65 px, where the tail joins
  Scene byBlend = scene;
  byBlend.correspondence = OutlineCorrespondence::kOutline;  // the same mesh, placed by the blend
  CHECK(quantile(stillDrift(byBlend, mesh, still), 0.5) > 0.5);  // 0.98
}

TEST_CASE("correspondence fallback: a key that folds under every edge length allowed is built with the corners that hold "
          "the outline less, and the note names what folded and what was used") {
  Scene scene = loadScene((std::filesystem::path(INBETWEEN_SOURCE_DIR) / "assets" / "continental-drift" / "scene.json").string());
  MultimeshBuildOptions options;
  options.refinements = 0;                // the first edge length only
  options.untangle.outerIterations = 0;  // Tutte's map alone: with the corners held, key "today" folds
  const BuiltScene built = buildMultimesh(scene, options);
  REQUIRE(built.multimesh);
  CHECK(built.fallback.find("corners \"vertices\" folded key \"today\" near (") != std::string::npos);
  CHECK(built.fallback.find("corners \"paired\" folded key \"today\" near (") != std::string::npos);
  CHECK(built.fallback.find("built with corners \"off\" and correspondence \"outline\" instead") != std::string::npos);
  CHECK(built.failedAttempts.empty());  // "off" built at the first edge length: no refinement to skip
  CHECK(built.attempts == 1);
  // What was used builds as the scene's own setting, with nothing tried before it.
  scene.corners = CornerHandling::kOff;
  const BuiltScene direct = buildMultimesh(scene, options);
  CHECK(direct.fallback.empty());
  CHECK(direct.multimesh->vertexCount() == built.multimesh->vertexCount());
}

namespace {

// The share of the silhouette at w = (1/2, 1/2) that its mirror image (x -> width - x) does not
// cover, and the other way round, over the silhouette's area: 0 for a symmetric inbetween.
double mirrorAsymmetry(const Scene& scene) {
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  const Multimesh& mesh = *built.multimesh;
  Interpolator solver(mesh, sceneFrameSetup(scene, mesh).interpolation, SolverOptions{});
  const InterpolationResult middle = solver.solve(Eigen::Vector2d(0.5, 0.5));
  const auto [width, height] = built.drawingSizes[0];
  const std::vector<char> in = silhouetteMask(mesh, middle.x, Eigen::Vector2d(0, 0), width, height);
  long area = 0, differ = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      area += in[y * width + x];
      differ += in[y * width + x] != in[y * width + (width - 1 - x)];
    }
  return static_cast<double>(differ) / area;
}

}  // namespace

TEST_CASE("correspondence: two mirrored keys give a mirror-symmetric middle inbetween whichever key is the reference "
          "(silhouette and its mirror image differ by under 1% of its area, by arc length and from the artwork)") {
  // Measured (silhouettes at 1 drawing px): "outline" 0.27% with key 0 or key 1 the reference;
  // "artwork" 0.46% and 0.17%. Before the loops. start was fitted by an affine map (a rigid
  // fit), "artwork" gave 1.14% and 0.45%.
  for (const OutlineCorrespondence correspondence : {OutlineCorrespondence::kOutline, OutlineCorrespondence::kArtwork})
    for (int reference = 0; reference < 2; ++reference) {
      Scene scene = correspondenceScene("lean-mirror", correspondence);
      scene.reference = reference;
      INFO("correspondence " << int(correspondence) << ", reference key " << reference);
      CHECK(mirrorAsymmetry(scene) < 0.01);
    }
}
