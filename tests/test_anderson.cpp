#include "anderson.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <random>

using namespace ib;

TEST_CASE("anderson: on a linear contraction it converges within n + 1 steps, plain iteration does not") {
  // G(x) = A x + b with a symmetric A of spectral radius 0.95 in n = 8 dimensions: with a
  // history at least n long, type-II Anderson acts like GMRES and finishes in about n steps.
  const int n = 8;
  std::mt19937 rng(42);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd Q = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return normal(rng); });
  Q = Eigen::HouseholderQR<Eigen::MatrixXd>(Q).householderQ();
  const Eigen::VectorXd eigen = Eigen::VectorXd::LinSpaced(n, -0.95, 0.95);
  const Eigen::MatrixXd A = Q * eigen.asDiagonal() * Q.transpose();
  const Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(n, [&] { return normal(rng); });
  const Eigen::VectorXd fixed = (Eigen::MatrixXd::Identity(n, n) - A).partialPivLu().solve(b);

  AndersonAcceleration anderson(10, 1);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), plain = x, next(n);
  for (int k = 0; k < n + 2; ++k) {
    const Eigen::VectorXd gx = A * x + b;
    anderson.next(gx, gx - x, next);
    x = next;
    plain = A * plain + b;
  }
  INFO("anderson error " << (x - fixed).norm() << ", plain error " << (plain - fixed).norm());
  REQUIRE((x - fixed).norm() < 1e-8 * fixed.norm());
  REQUIRE((plain - fixed).norm() > 0.1 * fixed.norm());
}

TEST_CASE("anderson: depth 0 returns the plain step") {
  AndersonAcceleration none(0, 1);
  const Eigen::VectorXd gx = Eigen::VectorXd::LinSpaced(5, 1, 5);
  Eigen::VectorXd out(5);
  none.next(gx, gx, out);
  REQUIRE(out == gx);
}
