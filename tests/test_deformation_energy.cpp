#include "interpolation/deformation_energy.h"
#include "testkit/shape_generators.h"

#include <catch2/catch.hpp>
#include <omp.h>

using namespace ib;

TEST_CASE("deformation energy: any split into blocks, on a team of any size, gives one block's energy and gradient") {
  // 2 keys on a 24 x 6 strip, evaluated at a third shape. Blocks own vertex ranges that do not
  // follow the triangles' order, so most triangles owe gradient to another block's vertices.
  const GridMesh grid = rectangleGrid(24, 6, 8.0, 2.0);
  const int n = static_cast<int>(grid.points.rows()), t = static_cast<int>(grid.triangles.size());
  const DeformationEnergy wd(grid.triangles, {grid.points, bendStrip(grid.points, 2.0)}, Eigen::VectorXd::Ones(t));
  const ActiveKeys keys{{0, 1}, {0.3, 0.7}};
  const Eigen::MatrixX2d x = waveStrip(stretchStrip(grid.points, 1.4, 0.8), 0.3, 1.0);
  const auto evaluate = [&](const RowSplit& vertices, const RowSplit& triangles, Eigen::MatrixX2d& gradient) {
    gradient.setZero(n, 2);
    return wd.evaluate(x, keys, gradient, vertices, triangles);
  };
  Eigen::MatrixX2d reference;
  const double energy = evaluate(RowSplit({0, n}), RowSplit({0, t}), reference);
  REQUIRE(energy > 0.1);
  const double scale = reference.cwiseAbs().maxCoeff();
  for (const auto& split : {std::pair{std::vector<int>{0, 50, n}, std::vector<int>{0, 130, t}},
                             std::pair{std::vector<int>{0, 0, 100, n}, std::vector<int>{0, 40, 41, t}}}) {
    const std::vector<int>& v = split.first;
    const std::vector<int>& k = split.second;  // not a structured binding: clang cannot use one inside omp
    Eigen::MatrixX2d gradient;
    CHECK(evaluate(RowSplit(v), RowSplit(k), gradient) == Approx(energy).epsilon(1e-12));
    CHECK((gradient - reference).cwiseAbs().maxCoeff() < 1e-12 * scale);
    double nestedEnergy = 0;
#pragma omp parallel num_threads(1)  // the evaluation's own region nests inside: a team of one
    nestedEnergy = evaluate(RowSplit(v), RowSplit(k), gradient);
    CHECK(nestedEnergy == Approx(energy).epsilon(1e-12));
    CHECK((gradient - reference).cwiseAbs().maxCoeff() < 1e-12 * scale);
  }
}

TEST_CASE("deformation energy: the shared metric's gradient is the derivative of its energy") {
  const GridMesh grid = rectangleGrid(8, 3, 8.0, 2.0);
  const int n = static_cast<int>(grid.points.rows()), t = static_cast<int>(grid.triangles.size());
  const DeformationEnergy wd(grid.triangles, {grid.points, stretchStrip(bendStrip(grid.points, 2.0), 3.0, 0.7)},
                             Eigen::VectorXd::Ones(t));
  const ActiveKeys keys{{0, 1}, {0.35, 0.65}};
  const Eigen::MatrixX2d x = waveStrip(stretchStrip(grid.points, 1.4, 0.8), 0.3, 1.0);
  const RowSplit vertices({0, n}), triangles({0, t});
  Eigen::MatrixX2d gradient = Eigen::MatrixX2d::Zero(n, 2), scratch(n, 2);
  wd.evaluate(x, keys, gradient, vertices, triangles, ShapeMetric::kShared);
  const double h = 1e-6;
  for (int v = 0; v < n; v += 7)
    for (int c = 0; c < 2; ++c) {
      Eigen::MatrixX2d plus = x, minus = x;
      plus(v, c) += h;
      minus(v, c) -= h;
      scratch.setZero();
      const double ep = wd.evaluate(plus, keys, scratch, vertices, triangles, ShapeMetric::kShared);
      scratch.setZero();
      const double em = wd.evaluate(minus, keys, scratch, vertices, triangles, ShapeMetric::kShared);
      CHECK((ep - em) / (2 * h) == Approx(gradient(v, c)).margin(1e-5 * gradient.cwiseAbs().maxCoeff()));
    }
}

TEST_CASE("deformation energy: at w = e_i the shared metric is the paper's energy and gradient") {
  const GridMesh grid = rectangleGrid(10, 4, 8.0, 2.0);
  const int n = static_cast<int>(grid.points.rows()), t = static_cast<int>(grid.triangles.size());
  const DeformationEnergy wd(grid.triangles, {grid.points, bendStrip(grid.points, 2.0)}, Eigen::VectorXd::Ones(t));
  const Eigen::MatrixX2d x = waveStrip(stretchStrip(grid.points, 1.4, 0.8), 0.3, 1.0);
  const RowSplit vertices({0, n}), triangles({0, t});
  for (int key = 0; key < 2; ++key) {
    const ActiveKeys keys{{key}, {1.0}};
    Eigen::MatrixX2d paper = Eigen::MatrixX2d::Zero(n, 2), shared = Eigen::MatrixX2d::Zero(n, 2);
    const double ep = wd.evaluate(x, keys, paper, vertices, triangles, ShapeMetric::kPerKey);
    const double es = wd.evaluate(x, keys, shared, vertices, triangles, ShapeMetric::kShared);
    CHECK(es == Approx(ep).epsilon(1e-10));
    CHECK((paper - shared).cwiseAbs().maxCoeff() < 1e-10 * paper.cwiseAbs().maxCoeff());
  }
}
