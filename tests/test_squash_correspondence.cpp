// A squash and a stretch matched as drawn (meshing/shared_boundary.cpp: alignedStart;
// meshing/boundary_sampling.cpp: corners paired by place), on tests/correspondence/chick-squash:
// a tall oval and a wide one fit each other about as well turned a quarter as stretched, and a
// corner where the beak meets the body lies about as far along the outline as one at a foot. The
// keys must still be matched as the animator drew them: beak to beak, nothing turned.
#include "core/png_image.h"
#include "meshing/multimesh_builder.h"
#include "scene/scene.h"

#include <catch2/catch.hpp>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

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

namespace {

// The drawn stripe's end on one side (+1 right, -1 left): the outermost column of RED pixels
// (tests/correspondence/draw.py, within 16/255) and their rows there, px (pixel edges: a pixel
// (x, y) spans [x, x + 1] x [y, y + 1]).
struct StripeEnd {
  double x = 0, top = 0, bottom = 0;
};

StripeEnd stripeEnd(const RgbaImage& image, int side) {
  int column = side > 0 ? -1 : image.width, top = image.height, bottom = -1;
  const auto red = [&](int x, int y) {
    const uint8_t* p = image.at(x, y);
    return p[3] > 250 && std::abs(p[0] - 215) < 16 && std::abs(p[1] - 60) < 16 && std::abs(p[2] - 50) < 16;
  };
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (red(x, y) && (side > 0 ? x > column : x < column)) column = x;
  for (int y = 0; y < image.height; ++y)
    if (column >= 0 && column < image.width && red(column, y)) top = std::min(top, y), bottom = std::max(bottom, y);
  return {column + 0.5 + 0.5 * side, static_cast<double>(top), bottom + 1.0};
}

// How far y lies outside [top, bottom], px (0 inside).
double outside(const StripeEnd& end, double y) { return std::max({0.0, end.top - y, y - end.bottom}); }

}  // namespace

TEST_CASE("correspondence artwork: where the chick's stripe meets its outline, the reference's boundary vertex there "
          "lies beside the stripe's end in every key (within 1 px of its rows, 4 px of its end), so the stripe maps "
          "onto itself") {
  Scene scene = loadScene((std::filesystem::path(INBETWEEN_SOURCE_DIR) / "tests" / "correspondence" / "chick-squash" /
                           "scene.json").string());
  scene.correspondence = OutlineCorrespondence::kArtwork;
  std::vector<RgbaImage> drawings;
  for (const KeySpec& key : scene.keys) drawings.push_back(readPng(key.drawing));
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  const Multimesh& mesh = *built.multimesh;
  for (int side : {-1, 1}) {
    INFO((side > 0 ? "right" : "left") << " end");
    // The reference's boundary vertices beside its stripe's end (within 4 px of it, in its rows).
    const StripeEnd referenceEnd = stripeEnd(drawings[scene.reference], side);
    std::vector<int> beside;
    for (int v : mesh.boundaryVertices(scene.reference)) {
      const Eigen::RowVector2d p = mesh.keyPositions(scene.reference).row(v);
      if (std::abs(p.x() - referenceEnd.x) < 4 && outside(referenceEnd, p.y()) == 0) beside.push_back(v);
    }
    REQUIRE(!beside.empty());
    for (int k = 0; k < mesh.keyCount(); ++k) {
      INFO("key " << scene.keys[k].name);
      const StripeEnd end = stripeEnd(drawings[k], side);
      for (int v : beside) {
        const Eigen::RowVector2d p = mesh.keyPositions(k).row(v);
        // Measured: at most 3.3 px across and 0.59 px off the rows (the squash's stripe has 5 rows
        // to the stand's 7); by arc length the squash key's left end is 2.4 px off its rows.
        CHECK(std::abs(p.x() - end.x) < 4);
        CHECK(outside(end, p.y()) < 1);
      }
    }
  }
}
