#include "core/error.h"
#include "interpolation/deformation_energy.h"
#include "testkit/reference_arap.h"
#include "testkit/shape_generators.h"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <cmath>

using namespace ib;

namespace {

// A 24 x 6 strip, 8 long, its two end columns as handles.
struct Strip {
  GridMesh grid = rectangleGrid(24, 6, 8.0, 2.0);
  std::vector<int> handles;
  Strip() {
    for (int row = 0; row < 6; ++row) {
      handles.push_back(row * 24);
      handles.push_back(row * 24 + 23);
    }
  }
  Eigen::MatrixX2d handleRows(const Eigen::MatrixX2d& x) const {
    Eigen::MatrixX2d out(handles.size(), 2);
    for (size_t h = 0; h < handles.size(); ++h) out.row(h) = x.row(handles[h]);
    return out;
  }
};

}  // namespace

TEST_CASE("reference ARAP: its energy is eq. 16's W_D for one key with kappa = 1") {
  // Cotangent form and deformation-gradient form of the same energy: sum_e (cot/2) |u_e|^2 is
  // area * |F - R|_F^2 for the linear map u of each triangle.
  const Strip strip;
  const ReferenceArap arap(strip.grid.points, strip.grid.triangles, strip.handles);
  const DeformationEnergy wd(strip.grid.triangles, {strip.grid.points},
                             Eigen::VectorXd::Ones(static_cast<int>(strip.grid.triangles.size())));
  const Eigen::MatrixX2d bent = stretchStrip(bendStrip(strip.grid.points, 2.0), 1.5, 0.7);
  Eigen::MatrixX2d gradient = Eigen::MatrixX2d::Zero(bent.rows(), 2);
  const ActiveKeys one{{0}, {1.0}};
  const double expected = wd.evaluate(bent, one, gradient, RowSplit({0, static_cast<int>(bent.rows())}),
                                      RowSplit({0, static_cast<int>(strip.grid.triangles.size())}));
  REQUIRE(expected > 0.1);
  REQUIRE(arap.energy(bent) == Approx(expected).epsilon(1e-10));
}

TEST_CASE("reference ARAP: the energy never increases from one iteration to the next") {
  const Strip strip;
  const ReferenceArap arap(strip.grid.points, strip.grid.triangles, strip.handles);
  const Eigen::MatrixX2d handles = strip.handleRows(bendStrip(strip.grid.points, 2.5));
  Eigen::MatrixX2d x = strip.grid.points;
  double previous = INFINITY;
  for (int k = 0; k < 40; ++k) {
    arap.iterate(x, handles);
    const double e = arap.energy(x);
    INFO("iteration " << k << ": " << e << " after " << previous);
    REQUIRE(std::isfinite(e));
    REQUIRE(e <= previous * (1 + 1e-12));
    previous = e;
  }
  REQUIRE(previous < 0.5 * arap.energy([&] {  // it made progress from the first step's state
    Eigen::MatrixX2d first = strip.grid.points;
    arap.iterate(first, handles);
    return first;
  }()));
}

TEST_CASE("reference ARAP: handles moved rigidly give a rigid copy of the rest shape") {
  const Strip strip;
  const ReferenceArap arap(strip.grid.points, strip.grid.triangles, strip.handles);
  const double angle = 0.4;
  Eigen::Matrix2d r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  const Eigen::MatrixX2d moved = (strip.grid.points * r.transpose()).rowwise() + Eigen::RowVector2d(3.0, -1.0);
  Eigen::MatrixX2d x = strip.grid.points;
  for (int k = 0; k < 2000; ++k) {  // the start has zero energy only until the handles move
    arap.iterate(x, strip.handleRows(moved));
    if (arap.energy(x) < 1e-24) break;
  }
  REQUIRE((x - moved).cwiseAbs().maxCoeff() < 1e-6 * 8.0);
}

TEST_CASE("reference ARAP: no handles, a bad handle or a degenerate triangle is the caller's error") {
  const Strip strip;
  REQUIRE_THROWS_AS(ReferenceArap(strip.grid.points, strip.grid.triangles, {}), std::invalid_argument);
  REQUIRE_THROWS_AS(ReferenceArap(strip.grid.points, strip.grid.triangles, {-1}), std::invalid_argument);
  Eigen::MatrixX2d flat = strip.grid.points;
  flat.col(1).setZero();
  REQUIRE_THROWS_AS(ReferenceArap(flat, strip.grid.triangles, strip.handles), std::invalid_argument);
}
