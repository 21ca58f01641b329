// Multimeshes built in code for the tests, each with a documented shape.
#pragma once

#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "testkit/shape_generators.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ib::test {

// A named multimesh and its shape size (bounding diagonal of key 0).
struct Fixture {
  std::string name;
  Multimesh mesh;
  double size;
};

// Strip of ~vertices vertices: rest, 180-degree bend (2 keys) plus stretch and wave (4 keys).
Fixture strip(int vertices, int keys);

// ib::gluedSquares (shape_generators.h) with n x n vertices a square.
Fixture gluedSquares(int n, double gap, double bulge);

// Every fixture a property should hold on (strips, glued squares).
std::vector<Fixture> allFixtures();

// Vertices of the glued squares' seam, left side and right side, bottom to top.
std::vector<int> seamLeft(int n);
std::vector<int> seamRight(int n);

// Solver options that solve to the minimizer: relative tolerance 1e-10, at most 3000 iterations.
SolverOptions tightSolverOptions();

// Largest distance between corresponding seam vertices.
double seamGap(const Eigen::MatrixX2d& x, int n);

}  // namespace ib::test
