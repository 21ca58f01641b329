#include "output/key_fidelity.h"
#include "output/key_rim.h"
#include "output/render_mesh.h"
#include "render_fixtures.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <set>

using namespace ib;
using namespace ib::render;
using namespace ib::test;

TEST_CASE("key rim: keyness is 1 at a key's weight e_i, 0 once the largest weight is a window below 1, and rises in between") {
  for (int m : {2, 3, 5})
    for (int k = 0; k < m; ++k) CHECK(keyness(Eigen::VectorXd::Unit(m, k)) == 1.0);
  CHECK(keyness((Eigen::VectorXd(2) << 0.9, 0.1).finished()) == 0.0);
  CHECK(keyness((Eigen::VectorXd(3) << 0.5, 0.3, 0.2).finished()) == 0.0);
  double last = 0;
  for (double w = 0.9; w <= 1.0 + 1e-12; w += 0.005) {
    const double s = keyness((Eigen::VectorXd(2) << 1 - w, w).finished());
    CHECK(s >= last);
    CHECK(s >= 0);
    CHECK(s <= 1);
    last = s;
  }
  CHECK(keyness((Eigen::VectorXd(2) << 0.05, 0.95).finished()) == Approx(0.5));
  CHECK(keyness((Eigen::VectorXd(2) << 0.3, 0.7).finished(), 0.5) > 0);  // a wider window reaches further
}

TEST_CASE("key rim: its points lie a rim's width from their boundary vertex, the edges' points outside the shape, in every key and frame") {
  const Multimesh mesh = squareGrid(5, 8, 8, 48, 2);  // [8, 56]^2
  const KeyRim rim = keyRimOf(mesh);
  CHECK(rim.width == 5);
  CHECK(rim.edges.size() == mesh.boundaryEdges().size());
  std::set<int> boundary;
  for (const Edge& e : mesh.boundaryEdges()) boundary.insert({e[0], e[1]});
  // A quad per boundary edge (2 points) and a fan of 8 spokes round each boundary vertex.
  CHECK(rim.points.size() == 2 * rim.edges.size() + 8 * boundary.size());
  CHECK(rim.triangles.size() == 2 * rim.edges.size() + 8 * boundary.size());
  // Moved and turned by 30 degrees: the rim follows the frame's boundary.
  Eigen::MatrixX2d x = mesh.keyPositions(0);
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (int v = 0; v < x.rows(); ++v) {
    const double dx = x(v, 0) - 32, dy = x(v, 1) - 32;
    x.row(v) << 100 + c * dx - s * dy, 50 + s * dx + c * dy;
  }
  for (const bool turned : {false, true}) {
    const Eigen::MatrixX2d& at = turned ? x : mesh.keyPositions(0);
    const Eigen::Vector2d u = turned ? Eigen::Vector2d(c, s) : Eigen::Vector2d(1, 0), w(-u.y(), u.x());  // the square's axes
    const Eigen::MatrixX2d points = rimPoints(rim, at);
    const Eigen::Vector2d centre = at.colwise().mean().transpose();
    for (size_t j = 0; j < rim.points.size(); ++j) {
      const Eigen::Vector2d p = points.row(static_cast<Eigen::Index>(j)).transpose();
      const Eigen::Vector2d v = at.row(rim.points[j].vertex).transpose();
      CHECK((p - v).norm() == Approx(5));
      if (rim.points[j].edge < 0) continue;
      // An edge's point is offset along its outward normal: farther from the square's centre,
      // across the square's side (24 px from the centre) by the rim's width.
      const Eigen::Vector2d side = (v - centre);
      const double across = std::max(std::abs(side.dot(u)), std::abs(side.dot(w)));
      const Eigen::Vector2d q = p - centre;
      const double acrossP = std::max(std::abs(q.dot(u)), std::abs(q.dot(w)));
      CHECK(across == Approx(24).margin(1e-9));
      CHECK(acrossP == Approx(29).margin(1e-9));
    }
  }
  // renderMeshOf gives each key the rim's UVs: its points in that key over the drawing's size.
  const RenderMesh renderMesh = renderMeshOf(mesh, {paintedImage(64, 64, [](int, int) { return std::array<uint8_t, 4>{0, 0, 0, 0}; }),
                                                    paintedImage(64, 64, [](int, int) { return std::array<uint8_t, 4>{0, 0, 0, 0}; })});
  REQUIRE(renderMesh.rimUV.size() == 2);
  CHECK((renderMesh.rimUV[1].cast<double>() * 64 - rimPoints(rim, mesh.keyPositions(1))).cwiseAbs().maxCoeff() < 1e-4);
  CHECK(renderMesh.drawings.size() == 2);
  CHECK(textureLayers(renderMesh).size() == 4);
}

namespace {

// A premultiplied image straightened as a frame is written (rounding: c * 255 / a).
RgbaImage straightened(RgbaImage image) {
  for (size_t p = 0; p < image.pixels.size(); p += 4) {
    const int a = image.pixels[p + 3];
    for (int ch = 0; ch < 3; ++ch) image.pixels[p + ch] = a == 0 ? 0 : uint8_t(std::min(255, (image.pixels[p + ch] * 255 + a / 2) / a));
  }
  return image;
}

}  // namespace

TEST_CASE("key fidelity: a drawing is itself at every scale, under both samplers, and a changed pixel is found where it is") {
  const RgbaImage drawing = paintedImage(12, 9, [](int x, int y) {
    return std::array<uint8_t, 4>{uint8_t(20 * x), uint8_t(25 * y), 200, uint8_t(x < 2 ? 0 : 90 + 15 * y)};
  });
  for (bool nearest : {true, false})
    for (int scale : {1, 2, 3}) {
      const RgbaImage magnified = magnifiedDrawing(drawing, scale, nearest);
      REQUIRE(magnified.width == 12 * scale);
      // magnifiedDrawing is premultiplied; compared as straight alpha against the drawing it is itself
      // within rounding (straightening a premultiplied pixel loses under a level per 255 / alpha).
      CHECK(keyFidelity(straightened(magnified), drawing, scale, nearest).over == 0);
    }
  RgbaImage changed = straightened(magnifiedDrawing(drawing, 1, true));
  changed.at(7, 4)[3] = static_cast<uint8_t>(changed.at(7, 4)[3] - 30);
  const KeyFidelity f = keyFidelity(changed, drawing, 1, true);
  CHECK(f.over == 1);
  CHECK(f.worstX == 7);
  CHECK(f.worstY == 4);
  CHECK(f.worst >= 20);
  CHECK_THROWS_AS(magnifiedDrawing(drawing, 0, true), std::invalid_argument);
}
