#include "linalg/anderson.h"

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

TEST_CASE("anderson: a row split by vertices over both columns gives the even split's iterates, on a team of any size") {
  // G(x) = A x + b on 2 x 300 unknowns (the x and y columns of 300 vertices), A diagonal with
  // entries in (0.5, 0.95): the same steps whatever block of rows a thread sums, up to rounding
  // (the history is stored in single precision, and the least-squares fit magnifies the
  // differences in the order of its sums: 1e-5 relative).
  const int n = 300;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.5, 0.95);
  const Eigen::VectorXd a = Eigen::VectorXd::NullaryExpr(2 * n, [&] { return uniform(rng); });
  const Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(2 * n, [&] { return uniform(rng); });
  const auto run = [&](AndersonAcceleration& anderson) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(2 * n), next(2 * n);
    for (int k = 0; k < 12; ++k) {
      const Eigen::VectorXd gx = a.cwiseProduct(x) + b;
      anderson.next(gx, gx - x, next);
      x = next;
    }
    return x;
  };
  AndersonAcceleration even(8, 2);
  const Eigen::VectorXd reference = run(even);
  for (const std::vector<int>& start : {std::vector<int>{0, 112, 300}, std::vector<int>{0, 0, 300}, std::vector<int>{0, 100, 200, 300}}) {
    AndersonAcceleration split(8, 1);
    split.setRowSplit(RowSplit(start), 2);
    CHECK((run(split) - reference).cwiseAbs().maxCoeff() < 1e-5 * reference.cwiseAbs().maxCoeff());
  }
}
