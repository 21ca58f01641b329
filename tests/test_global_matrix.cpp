#include "interpolation/global_matrix.h"
#include "testkit/fixtures.h"

#include <catch2/catch.hpp>
#include <memory>
#include <random>
#include <stdexcept>

using namespace ib;

namespace {

// The energies of the glued squares (side x side vertices each, cohesive pairs along the seam in
// key 0) and a GlobalMatrix over them on one thread, in the mesh's own vertex order.
struct GluedSquaresH {
  explicit GluedSquaresH(int side = 8, CohesiveParams params = {})
      : f(test::gluedSquares(side, 0.5, 0.2)), cohesive(f.mesh, keys, params) {}
  test::Fixture f;
  std::vector<Eigen::MatrixX2d> keys{f.mesh.keyPositions(0), f.mesh.keyPositions(1)};
  DeformationEnergy deformation{f.mesh.triangles(), keys,
                                Eigen::VectorXd::Ones(static_cast<int>(f.mesh.triangles().size()))};
  CohesiveEnergy cohesive;
  NonOverlap nonOverlap{f.mesh, 3.0};
  int n = f.mesh.vertexCount();

  std::unique_ptr<GlobalMatrix> make(double tie, bool withNonOverlap) {
    const GlobalMatrixSources sources{&deformation, &cohesive, withNonOverlap ? &nonOverlap : nullptr, tie, 1.0};
    return std::make_unique<GlobalMatrix>(sources, n, std::vector<int>{0, n}, 1);
  }
};

}  // namespace

TEST_CASE("global matrix: translations are in the kernel of the ARAP and cohesive terms") {
  // H 1 = (tie + c_v + k_O [v on a boundary]) 1, so solving with that right-hand side must give 1
  // in both columns. Springs of order one keep H well conditioned for the single-precision factor.
  GluedSquaresH g;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> spring(0.5, 2.0);
  Eigen::VectorXd springs(g.n);
  for (int v = 0; v < g.n; ++v) springs(v) = spring(random);
  const std::vector<char> held(g.cohesive.terms().size(), 1);
  REQUIRE(!held.empty());
  const Eigen::VectorXd w = Eigen::Vector2d(0.4, 0.6);
  for (bool withNonOverlap : {false, true}) {
    INFO("non-overlap " << withNonOverlap);
    auto H = g.make(0.25, withNonOverlap);
    H->factorize({w, springs, held});
    Eigen::VectorXd diagonal = springs.array() + 0.25;
    if (withNonOverlap)
      for (int v : g.nonOverlap.allBoundaryVertices()) diagonal(v) += g.nonOverlap.stiffness();
    Eigen::MatrixX2d rhs(g.n, 2);
    rhs << diagonal, diagonal;
    H->factor().solve(rhs);
    CHECK((rhs.array() - 1.0).abs().maxCoeff() < 1e-4);
    // A stretch is not in the kernel: the same check on x itself must fail, or it proves nothing.
    Eigen::MatrixX2d stretch = g.keys[0];
    Eigen::MatrixX2d image = stretch.array().colwise() * diagonal.array();
    H->factor().solve(image);
    CHECK((image - stretch).cwiseAbs().maxCoeff() > 1e-2);
  }
}

TEST_CASE("global matrix: the factor models a frame only near the weights, springs and pairs it was built for") {
  // The paper's timing: the pairs' weights move with w alone (the release ramps: the next case).
  CohesiveParams tau;
  tau.timing = CutTiming::kTau;
  GluedSquaresH g(8, tau);
  auto H = g.make(1e-3, false);
  const std::vector<char> held(g.cohesive.terms().size(), 1);
  std::vector<char> released = held;
  released.front() = 0;
  const Eigen::VectorXd none;
  const Eigen::VectorXd springs = Eigen::VectorXd::Constant(g.n, 1.0);
  const Eigen::VectorXd w0 = Eigen::Vector2d(0.5, 0.5), near = Eigen::Vector2d(0.2, 0.8), far = Eigen::Vector2d(1, 0);
  CHECK_FALSE(H->models({w0, none, held}, 1.0));  // nothing factorized yet
  H->factorize({w0, none, held});
  CHECK(H->models({w0, none, held}, 1.0));
  CHECK(H->models({near, none, held}, 1.0));       // |w - w0|_1 = 0.6
  CHECK_FALSE(H->models({near, none, held}, 0.5));
  CHECK_FALSE(H->models({far, none, held}, 0.5)); // |w - w0|_1 = 1
  CHECK(H->models({w0, none, held}, 0.0));          // distance 0: the very same weights only
  CHECK_FALSE(H->models({near, none, held}, 0.0));
  CHECK_FALSE(H->models({w0, none, released}, 1.0));
  CHECK_FALSE(H->models({w0, springs, held}, 1.0)); // springs where H has none
  CHECK(H->held() == held);

  H->factorize({w0, springs, held});
  CHECK(H->models({w0, Eigen::VectorXd(springs * 1.05), held}, 1.0));
  CHECK_FALSE(H->models({w0, Eigen::VectorXd(springs * 1.5), held}, 1.0));
  CHECK_FALSE(H->models({w0, none, held}, 1.0));
  H->invalidate();
  CHECK_FALSE(H->models({w0, springs, held}, 1.0));
}

TEST_CASE("global matrix: under release timing the factor models a frame only while every cut's ramp is within a tenth of its own") {
  GluedSquaresH g;  // the default timing: the seam is closed in key 0, open in key 1
  auto H = g.make(1e-3, false);
  const std::vector<char> held(g.cohesive.terms().size(), 1);
  const Eigen::VectorXd none;
  const Eigen::VectorXd w0 = Eigen::Vector2d(0.5, 0.5);
  H->factorize({w0, none, held});
  const double r0 = g.cohesive.ramp(0, w0);
  REQUIRE(r0 > 0.1);
  REQUIRE(r0 < 0.9);
  const Eigen::VectorXd small = Eigen::Vector2d(0.47, 0.53), large = Eigen::Vector2d(0.3, 0.7);
  CHECK(std::abs(g.cohesive.ramp(0, small) - r0) < 0.1);
  CHECK(H->models({small, none, held}, 1.0));
  CHECK(std::abs(g.cohesive.ramp(0, large) - r0) > 0.1);
  CHECK_FALSE(H->models({large, none, held}, 1.0));  // |w - w0|_1 = 0.4, within the distance
}

TEST_CASE("global matrix: updating the factor for pairs that let go or engage solves as a factorization with those pairs does") {
  // Large enough that a few rank-one updates cost less than a factorization.
  GluedSquaresH g(30);
  const std::vector<char> held(g.cohesive.terms().size(), 1);
  REQUIRE(held.size() >= 20);
  std::vector<char> released = held;  // every fifth pair lets go
  for (size_t j = 0; j < released.size(); j += 5) released[j] = 0;
  const Eigen::VectorXd none;
  const Eigen::VectorXd w = Eigen::Vector2d(0.7, 0.3);
  std::mt19937 random(19);
  std::uniform_real_distribution<double> value(-1, 1);
  Eigen::MatrixX2d b(g.n, 2);
  for (int i = 0; i < g.n; ++i) b.row(i) << value(random), value(random);
  const auto solved = [&](const GlobalMatrix& H) {
    Eigen::MatrixX2d x = b;
    H.factor().solve(x);
    return x;
  };
  auto updated = g.make(1e-3, false);
  auto fresh = g.make(1e-3, false);
  CHECK_THROWS_AS(updated->updateHeld(released), std::logic_error);  // nothing factorized yet
  updated->factorize({w, none, held});
  const Eigen::MatrixX2d before = solved(*updated);
  REQUIRE(updated->updateHeld(released));
  CHECK(updated->held() == released);
  CHECK(updated->models({w, none, released}, 0.0));
  fresh->factorize({w, none, released});
  // Both factors are single precision; the seam's springs (lambda l / 3) make H stiff along it.
  const Eigen::MatrixX2d expected = solved(*fresh);
  CHECK((solved(*updated) - expected).norm() < 1e-4 * expected.norm());
  // Letting go changes the solution by 0.5% here: 50 times the tolerance above.
  CHECK((before - expected).norm() > 2e-3 * expected.norm());
  REQUIRE(updated->updateHeld(held));
  CHECK((solved(*updated) - before).norm() < 1e-4 * before.norm());
}
