#include "error.h"
#include "offscreen_renderer.h"
#include "render_fixtures.h"
#include "shape_generators.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

using namespace ib;
using namespace ib::render;
using ib::test::frameOf;
using ib::test::paintedImage;
using ib::test::pixel;

namespace {

using Colour = std::array<uint8_t, 4>;

// Two halves of a 32 x 32 drawing-pixel square, [8, 24] and [24, 40] along x and [0, 32] along y,
// with their own vertices along the cut x = 24. Key 0 draws the square whole (the cut glued,
// cohesive pairs along it); key 1 draws the right half 8 pixels further right (the cut open).
struct CutSquare {
  Multimesh mesh;
  std::vector<int> left, right;  // the vertices on the cut, bottom to top, of each half
};

CutSquare cutSquare() {
  const GridMesh half = rectangleGrid(5, 9, 16, 32);  // 4-pixel cells
  const int n = static_cast<int>(half.points.rows());
  std::vector<Triangle> triangles = half.triangles;
  for (Triangle t : half.triangles) {
    for (int& v : t) v += n;
    triangles.push_back(t);
  }
  Eigen::MatrixX2d glued(2 * n, 2);
  glued.topRows(n) = half.points;
  glued.bottomRows(n) = half.points;
  glued.col(0).head(n).array() += 8;
  glued.col(0).tail(n).array() += 24;
  Eigen::MatrixX2d open = glued;
  open.col(0).tail(n).array() += 8;
  CutSquare out{Multimesh(2 * n, triangles), {}, {}};
  for (int v = 0; v < n; ++v)
    if (half.points(v, 0) == 16) out.left.push_back(v);
    else if (half.points(v, 0) == 0) out.right.push_back(v + n);
  std::vector<CohesivePair> pairs;
  for (size_t j = 0; j + 1 < out.left.size(); ++j)
    pairs.push_back({out.left[j], out.left[j + 1], out.right[j], out.right[j + 1]});
  out.mesh.addKey(glued, pairs, {});
  out.mesh.addKey(open, {}, {});
  out.mesh.validate();
  return out;
}

// 48 x 32 drawings: key 0 opaque teal wherever the square is; key 1 opaque orange except the
// open cut x in [24, 32), which is transparent: sampled at the cut's sides, its texels blend
// with the transparent ones, as antialiased line art does along an outline.
std::vector<RgbaImage> cutSquareArtwork() {
  return {paintedImage(48, 32, [](int, int) { return Colour{20, 150, 140, 255}; }),
          paintedImage(48, 32, [](int x, int) { return x >= 24 && x < 32 ? Colour{0, 0, 0, 0} : Colour{240, 120, 20, 255}; })};
}

Eigen::MatrixX2d shiftedRight(const Eigen::MatrixX2d& x, const std::vector<int>& vertices, double dx) {
  Eigen::MatrixX2d out = x;
  for (int v : vertices) out(v, 0) += dx;
  return out;
}

}  // namespace

TEST_CASE("seams: gaps under `glued` target pixels are welded, gaps of `open` or more left alone") {
  const CutSquare cut = cutSquare();
  const Seams seams = renderMeshOf(cut.mesh, cutSquareArtwork()).seams;
  REQUIRE(seams.pairs.size() == 8);
  REQUIRE(seams.partners.size() == 9);
  const Eigen::MatrixX2d glued = cut.mesh.keyPositions(0);
  const SeamWeldOptions options;  // 0.5 and 1.5 target pixels

  // The right half's cut 0.2 drawing pixels off, shown at 1x: welded shut at the midpoint.
  const Eigen::MatrixX2d nearly = shiftedRight(glued, cut.right, 0.2);
  const SeamWeld weld = weldSeams(nearly, seams, 1.0, options);
  for (size_t j = 0; j < cut.left.size(); ++j) {
    const int l = cut.left[j], r = cut.right[j];
    CHECK((weld.positions.row(l) - weld.positions.row(r)).norm() < 1e-12);
    CHECK(weld.positions(l, 0) == Approx(24.1));
    CHECK(weld.closure[l] == 1.0f);
    CHECK(weld.closure[r] == 1.0f);
  }
  // Off the cut nothing moves; the vertices one 4-pixel cell from it take its closure, so the
  // triangles along it have closure 1 throughout; the rest have 0.
  for (int v = 0; v < cut.mesh.vertexCount(); ++v) {
    const double fromCut = std::abs(glued(v, 0) - 24);
    if (fromCut == 0) continue;
    INFO("vertex " << v << ", " << fromCut << " px from the cut");
    CHECK(weld.closure[v] == (fromCut == 4 ? 1.0f : 0.0f));
    CHECK(weld.positions.row(v) == nearly.row(v));
  }

  // The same 0.2 pixels shown 10x larger are 2 target pixels: a gap the picture can show, kept.
  const SeamWeld zoomed = weldSeams(nearly, seams, 10.0, options);
  CHECK(zoomed.positions == nearly);
  CHECK(*std::max_element(zoomed.closure.begin(), zoomed.closure.end()) == 0.0f);

  // Between the thresholds a gap narrows, continuously and keeping its order.
  double previous = 0;
  for (double gap = 0.5; gap <= 1.6; gap += 0.1) {
    const SeamWeld w = weldSeams(shiftedRight(glued, cut.right, gap), seams, 1.0, options);
    const double shown = (w.positions.row(cut.right[3]) - w.positions.row(cut.left[3])).norm();
    INFO("gap " << gap << " shown as " << shown);
    CHECK(shown >= previous);
    CHECK(shown <= gap + 1e-12);
    const double c = std::clamp(1.5 - gap, 0.0, 1.0);
    CHECK(shown == Approx(gap * (1 - c) / (1 + c)).margin(1e-12));
    CHECK(w.closure[cut.left[3]] == Approx(std::clamp(1.5 - gap, 0.0, 1.0)).margin(1e-6));
    previous = shown;
  }
  CHECK_THROWS_AS(weldSeams(glued, seams, 1.0, {1.0, 1.0}), InputError);
  CHECK_THROWS_AS(weldSeams(glued, seams, 0.0, options), InputError);
}

TEST_CASE("seams: a pair the solver says holds is welded shut at any gap; the others follow the pixel rule") {
  // Just before a stretched cut lets go its held pairs open by a pixel or more at the picture's
  // scale: with the solver's flags they stay shut, without them they would show as a speck.
  const CutSquare cut = cutSquare();
  const Seams seams = renderMeshOf(cut.mesh, cutSquareArtwork()).seams;
  REQUIRE(seams.pairOfTerm.size() == 8);
  std::vector<char> holding(8, 0);
  std::fill(holding.begin(), holding.begin() + 4, 1);  // pairs 0-3 hold: vertices 0-4 of each side
  const Eigen::MatrixX2d apart = shiftedRight(cut.mesh.keyPositions(0), cut.right, 2.0);
  const SeamWeld plain = weldSeams(apart, seams, 1.0);
  const SeamWeld held = weldSeams(apart, seams, 1.0, {}, &holding);
  for (size_t j = 0; j < cut.left.size(); ++j) {
    const int l = cut.left[j], r = cut.right[j];
    INFO("vertex pair " << j);
    CHECK((plain.positions.row(l) - plain.positions.row(r)).norm() == Approx(2.0));
    CHECK(plain.closure[l] == 0.0f);
    if (j <= 4) {
      CHECK((held.positions.row(l) - held.positions.row(r)).norm() < 1e-12);
      CHECK(held.positions(l, 0) == Approx(25.0));
      CHECK(held.closure[l] == 1.0f);
      CHECK(held.closure[r] == 1.0f);
    } else {
      CHECK(held.positions.row(l) == apart.row(l));
      CHECK(held.positions.row(r) == apart.row(r));
      CHECK(held.closure[l] == 0.0f);
    }
  }
  const std::vector<char> tooFew(7, 1);
  CHECK_THROWS_AS(weldSeams(apart, seams, 1.0, {}, &tooFew), InputError);
}

TEST_CASE("seams: the tip of a cut, its own partner, takes its pair's closure") {
  // Edges (0, 1) and (0, 2) of a slit, glued: vertex 0 is the tip, vertex 3 lies off the cut.
  Eigen::MatrixX2d key(4, 2);
  key << 0, 0, 10, 0.1, 10, -0.1, 20, 0;
  Seams seams;
  seams.pairs.push_back({0, 1, 0, 2});
  seams.partners.push_back({1, 2});
  const SeamWeld weld = weldSeams(key, seams, 1.0);
  CHECK(weld.closure[0] == 1.0f);
  CHECK(weld.closure[3] == 0.0f);
  CHECK(weld.positions(1, 1) == Approx(0).margin(1e-12));
  CHECK(weld.positions(0, 0) == 0);
}

TEST_CASE("renderer: a glued cut shows no seam where another key draws it open; an open cut stays open") {
  const vk::VulkanContext context = test::validatedContext();
  const CutSquare cut = cutSquare();
  OffscreenOptions target;
  target.width = 192;
  target.height = 128;
  OffscreenRenderer renderer(context, renderMeshOf(cut.mesh, cutSquareArtwork()), target);
  const ViewBox view{0, 0, 48, 32};  // 4 target pixels per drawing pixel
  const Eigen::VectorXd half = Eigen::Vector2d(0.5, 0.5);

  // Glued within a tenth of a drawing pixel, as the solver leaves a cohesive zone: opaque across
  // the cut, where a plain blend of the two keys' alpha would leave a line at 3/4 opacity.
  for (double gap : {0.0, 0.1}) {
    const Eigen::MatrixX2d x = shiftedRight(cut.mesh.keyPositions(0), cut.right, gap);
    const RgbaImage image = renderer.render(frameOf(x, half, view));
    double lowest = 255;
    for (int py = 8; py < 120; ++py)
      for (int px = 40; px < 152; ++px) lowest = std::min(lowest, pixel(image, px, py)[3]);
    INFO("gap " << gap << " drawing pixels: lowest alpha inside the square " << lowest);
    CHECK(lowest >= 253);
  }

  // Open by 8 drawing pixels: the cut shows as a gap, transparent in its middle, and each half
  // keeps the blend of the two keys' colours.
  const Eigen::MatrixX2d open = cut.mesh.keyPositions(1);
  const RgbaImage image = renderer.render(frameOf(open, half, view));
  CHECK(pixel(image, 112, 64)[3] <= 2);
  for (int px : {64, 160}) {
    const std::array<double, 4> p = pixel(image, px, 64);
    CHECK(p[3] >= 253);
    CHECK(std::abs(p[0] - 0.5 * (20 + 240)) <= 3);
    CHECK(std::abs(p[1] - 0.5 * (150 + 120)) <= 3);
  }
  CHECK(context.validationMessages().empty());
}
