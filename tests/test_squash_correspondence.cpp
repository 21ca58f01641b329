// A squash and a stretch matched as drawn (meshing/shared_boundary.cpp: alignedStart;
// meshing/boundary_sampling.cpp: corners paired by place), on tests/correspondence/chick-squash:
// a tall oval and a wide one fit each other about as well turned a quarter as stretched, and a
// corner where the beak meets the body lies about as far along the outline as one at a foot. The
// keys must still be matched as the animator drew them: beak to beak, nothing turned.
#include "meshing/multimesh_builder.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>
#include <Eigen/Dense>
#include <cmath>
#include <filesystem>

using namespace ib;

namespace {

// The angle (deg) of the rotation part of the least-squares affine map of `from`'s vertices onto
// `to`'s (n x 2 each): how far the correspondence turns the key as a whole.
double turnOfFit(const Eigen::MatrixX2d& from, const Eigen::MatrixX2d& to) {
  const Eigen::RowVector2d cf = from.colwise().mean(), ct = to.colwise().mean();
  const Eigen::MatrixX2d f = from.rowwise() - cf, t = to.rowwise() - ct;
  const Eigen::Matrix2d A = (t.transpose() * f) * (f.transpose() * f).inverse();  // 2x2, f -> t
  return std::abs(std::atan2(A(1, 0) - A(0, 1), A(0, 0) + A(1, 1))) * 180 / M_PI;
}

int rightmost(const Eigen::MatrixX2d& positions) {
  int best = 0;
  for (int v = 1; v < positions.rows(); ++v)
    if (positions(v, 0) > positions(best, 0)) best = v;
  return best;
}

}  // namespace

TEST_CASE("correspondence: the chick's squash and stretch are matched as drawn under either correspondence: the "
          "reference's beak tip on each key's beak tip within 1.5 px, and no key's map turned by more than 5 deg") {
  const OutlineCorrespondence correspondence = GENERATE(OutlineCorrespondence::kOutline, OutlineCorrespondence::kArtwork);
  Scene scene = loadScene((std::filesystem::path(INBETWEEN_SOURCE_DIR) / "tests" / "correspondence" / "chick-squash" /
                           "scene.json").string());
  scene.correspondence = correspondence;
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  const Multimesh& mesh = *built.multimesh;
  const Eigen::MatrixX2d& reference = mesh.keyPositions(scene.reference);
  // The beak's tip is the drawing's rightmost point in every key (tests/correspondence/draw.py).
  const int tip = rightmost(reference);
  for (int k = 0; k < mesh.keyCount(); ++k) {
    INFO("key " << scene.keys[k].name << (correspondence == OutlineCorrespondence::kArtwork ? ", artwork" : ", outline"));
    const Eigen::MatrixX2d& key = mesh.keyPositions(k);
    CHECK((key.row(tip) - key.row(rightmost(key))).norm() < 1.5);
    // Measured: squash 2.2 / 2.3 deg, stretch 2.4 / 4.2 (outline / artwork); with the rigid start
    // and corners paired by fraction alone the inbetweens turned the chick by 30-40 deg.
    CHECK(turnOfFit(reference, key) < 5);
  }
}
