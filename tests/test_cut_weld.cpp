#include "core/error.h"
#include "output/render_mesh.h"
#include "render_fixtures.h"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <cmath>

using namespace ib;
using namespace ib::render;
using namespace ib::test;

TEST_CASE("cutSides: gaps under `glued` target pixels are welded, gaps of `open` or more left alone") {
  const CutSquare cut = cutSquare();
  const CutSides cutSides = renderMeshOf(cut.mesh, cutSquareArtwork()).cutSides;
  REQUIRE(cutSides.pairs.size() == 8);
  REQUIRE(cutSides.partners.size() == 9);
  const Eigen::MatrixX2d glued = cut.mesh.keyPositions(0);
  const CutWeldOptions options;  // 0.5 and 1.5 target pixels

  // The right half's cut 0.2 drawing pixels off, shown at 1x: welded shut at the midpoint.
  const Eigen::MatrixX2d nearly = shiftedRight(glued, cut.right, 0.2);
  const CutWeld weld = weldCuts(nearly, cutSides, 1.0, options);
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
  const CutWeld zoomed = weldCuts(nearly, cutSides, 10.0, options);
  CHECK(zoomed.positions == nearly);
  CHECK(*std::max_element(zoomed.closure.begin(), zoomed.closure.end()) == 0.0f);

  // Between the thresholds a gap narrows, continuously and keeping its order.
  double previous = 0;
  for (double gap = 0.5; gap <= 1.6; gap += 0.1) {
    const CutWeld w = weldCuts(shiftedRight(glued, cut.right, gap), cutSides, 1.0, options);
    const double shown = (w.positions.row(cut.right[3]) - w.positions.row(cut.left[3])).norm();
    INFO("gap " << gap << " shown as " << shown);
    CHECK(shown >= previous);
    CHECK(shown <= gap + 1e-12);
    const double c = std::clamp(1.5 - gap, 0.0, 1.0);
    CHECK(shown == Approx(gap * (1 - c) / (1 + c)).margin(1e-12));
    CHECK(w.closure[cut.left[3]] == Approx(std::clamp(1.5 - gap, 0.0, 1.0)).margin(1e-6));
    previous = shown;
  }
  CHECK_THROWS_AS(weldCuts(glued, cutSides, 1.0, {1.0, 1.0}), std::invalid_argument);
  CHECK_THROWS_AS(weldCuts(glued, cutSides, 0.0, options), std::invalid_argument);
}

TEST_CASE("cutSides: a pair the solver says holds is welded shut at any gap, the others follow the pixel rule") {
  // Just before a stretched cut lets go its held pairs open by a pixel or more at the picture's
  // scale: with the solver's flags they stay shut, without them they would show as a speck.
  const CutSquare cut = cutSquare();
  const CutSides cutSides = renderMeshOf(cut.mesh, cutSquareArtwork()).cutSides;
  REQUIRE(cutSides.pairOfTerm.size() == 8);
  std::vector<char> heldPairs(8, 0);
  std::fill(heldPairs.begin(), heldPairs.begin() + 4, 1);  // pairs 0-3 hold: vertices 0-4 of each side
  const Eigen::MatrixX2d apart = shiftedRight(cut.mesh.keyPositions(0), cut.right, 2.0);
  const CutWeld plain = weldCuts(apart, cutSides, 1.0);
  const CutWeld held = weldCuts(apart, cutSides, 1.0, {}, &heldPairs);
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
  CHECK_THROWS_AS(weldCuts(apart, cutSides, 1.0, {}, &tooFew), std::invalid_argument);
}

TEST_CASE("cutSides: the tip of a cut, its own partner, takes its pair's closure") {
  // Edges (0, 1) and (0, 2) of a slit, glued: vertex 0 is the tip, vertex 3 lies off the cut.
  Eigen::MatrixX2d key(4, 2);
  key << 0, 0, 10, 0.1, 10, -0.1, 20, 0;
  CutSides cutSides;
  cutSides.pairs.push_back({0, 1, 0, 2});
  cutSides.partners.push_back({1, 2});
  const CutWeld weld = weldCuts(key, cutSides, 1.0);
  CHECK(weld.closure[0] == 1.0f);
  CHECK(weld.closure[3] == 0.0f);
  CHECK(weld.positions(1, 1) == Approx(0).margin(1e-12));
  CHECK(weld.positions(0, 0) == 0);
}
