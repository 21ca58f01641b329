// Geometric checks shared by the multimesh, Comesh, interpolation and animation tests.
#pragma once

#include "meshing/key_shape.h"
#include "multimesh/multimesh.h"

#include <Eigen/Core>
#include <vector>

namespace test {

// Distance from p to the nearest segment of the key's loops (outlines and cut sides), px.
double distanceToShape(const ib::KeyShape& shape, const Eigen::Vector2d& p);

// Vertices on the mesh boundary.
std::vector<int> meshBoundary(const ib::Multimesh& mesh);

// The mesh boundary at positions x (n x 2) as segments (pairs of vertex indices).
std::vector<std::array<int, 2>> boundaryEdges(const ib::Multimesh& mesh);

// Distance from p to the nearest boundary segment of the mesh at positions x.
double distanceToBoundary(const std::vector<std::array<int, 2>>& edges, const Eigen::MatrixX2d& x,
                          const Eigen::Vector2d& p);

// ARAP distortion of one triangle at x (n x 2): sum_i w_i |F_i - R_i|_F^2 over the keys, with
// F_i = D(x) D(X_i)^{-1} and R_i its closest rotation; unweighted by kappa and area.
double arapDistortion(const ib::Multimesh& mesh, const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, int triangle);

// The part of the shared metric's energy (interpolation/shape_metric.h) that the mesh leaves a
// triangle: with M = sum_i w_i a_i B_i B_i^T (a_i its area in key i, B_i its inverse edge matrix
// there), R_i the rotation closest to D M D_i^T and D* = sum_i w_i R_i D_i the blend of its
// rotated key triangles, tr((D - D*) M (D - D*)^T) / sum_i w_i a_i: zero where the triangle is
// its blend (the rest of its energy, the keys' spread about D*, no placement can change).
double sharedMetricDistortion(const ib::Multimesh& mesh, const Eigen::MatrixX2d& x, const Eigen::VectorXd& w, int triangle);

}  // namespace test
