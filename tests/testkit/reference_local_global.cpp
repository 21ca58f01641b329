#include "testkit/reference_local_global.h"

#include "interpolation/deformation_energy.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <cmath>

namespace ib::test {

Eigen::MatrixX2d referenceLocalGlobal(const Multimesh& mesh, const Eigen::VectorXd& w, const CohesiveParams& params,
                                      const Eigen::MatrixX2d& start, int maxIterations, double stepTolerance) {
  const int n = mesh.vertexCount(), m = mesh.keyCount();
  const auto tris = mesh.triangles();
  double meanArea = 0;
  std::vector<Eigen::MatrixX2d> X;
  for (int i = 0; i < m; ++i) {
    X.push_back(mesh.keyPositions(i));
    for (const auto& t : tris) meanArea += signedArea(X[i].row(t[0]), X[i].row(t[1]), X[i].row(t[2])) / m;
  }
  const double s = std::sqrt(meanArea);
  for (auto& Xi : X) Xi /= s;
  const Eigen::VectorXd kappa = mesh.stiffnesses();
  Eigen::MatrixX2d x = start / s;
  // Unknown layout: 2v + coordinate.
  const auto edgeMatrix = [&](const Eigen::MatrixX2d& P, const Triangle& t) {
    Eigen::Matrix2d D;
    D.col(0) = (P.row(t[1]) - P.row(t[0])).transpose();
    D.col(1) = (P.row(t[2]) - P.row(t[0])).transpose();
    return D;
  };
  for (int it = 0; it < maxIterations; ++it) {
    std::vector<Eigen::Triplet<double>> K;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * n);
    for (size_t k = 0; k < tris.size(); ++k) {
      const Triangle& t = tris[k];
      const Eigen::Matrix2d D = edgeMatrix(x, t);
      for (int i = 0; i < m; ++i) {
        if (w(i) <= 0) continue;
        const Eigen::Matrix2d Dr = edgeMatrix(X[i], t);
        const Eigen::Matrix2d B = Dr.inverse();
        const double c = w(i) * kappa(k) * 0.5 * Dr.determinant();
        const Eigen::Matrix2d R = closestRotation(D * B);
        // Energy c |D B - R|^2: quadratic 2c B B^T per coordinate, linear term 2c R B^T.
        const Eigen::Matrix2d Mq = 2 * c * B * B.transpose();
        const Eigen::Matrix2d T = 2 * c * R * B.transpose();
        const double E[2][3] = {{-1, 1, 0}, {-1, 0, 1}};
        for (int r = 0; r < 3; ++r) {
          for (int q = 0; q < 3; ++q) {
            double value = 0;
            for (int a = 0; a < 2; ++a)
              for (int bb = 0; bb < 2; ++bb) value += E[a][r] * Mq(a, bb) * E[bb][q];
            for (int d = 0; d < 2; ++d) K.emplace_back(2 * t[r] + d, 2 * t[q] + d, value);
          }
          for (int d = 0; d < 2; ++d) b(2 * t[r] + d) += E[0][r] * T(d, 0) + E[1][r] * T(d, 1);
        }
      }
    }
    for (int i = 0; i < m; ++i) {
      if (w(i) <= 0) continue;
      for (const CohesivePair& p : mesh.cohesivePairs(i)) {
        const double l = (X[i].row(p.a) - X[i].row(p.b)).norm();
        const Eigen::Vector2d u = (x.row(p.a) - x.row(p.c)).transpose(), v = (x.row(p.b) - x.row(p.d)).transpose();
        Eigen::Vector2d sdir = (x.row(p.a) + x.row(p.c) - x.row(p.b) - x.row(p.d)).transpose();
        const Eigen::Vector2d xhat = sdir.norm() > 1e-12 ? Eigen::Vector2d(sdir.normalized())
                                                          : Eigen::Vector2d((X[i].row(p.a) - X[i].row(p.b)).normalized());
        const Eigen::Matrix2d P = params.alpha * Eigen::Matrix2d::Identity() + (1 - 2 * params.alpha) * xhat * xhat.transpose();
        const double scale = l / 3 * params.lambda;
        if (scale * (u.dot(P * u) + u.dot(P * v) + v.dot(P * v)) >= params.tau) continue;
        // w scale [u;v]^T [[P, P/2],[P/2, P]] [u;v]: Hessian w scale [[2P, P],[P, 2P]] in (u, v).
        const int verts[4] = {p.a, p.c, p.b, p.d};
        const double sign[4] = {1, -1, 1, -1};
        for (int r = 0; r < 4; ++r)
          for (int q = 0; q < 4; ++q) {
            const double block = (r / 2 == q / 2) ? 2.0 : 1.0;
            for (int d = 0; d < 2; ++d)
              for (int e = 0; e < 2; ++e)
                K.emplace_back(2 * verts[r] + d, 2 * verts[q] + e, w(i) * scale * block * sign[r] * sign[q] * P(d, e));
          }
      }
    }
    // A tiny proximal term pins the free rigid translation without moving the fixed point.
    const double eps = 1e-10;
    for (int k = 0; k < 2 * n; ++k) K.emplace_back(k, k, eps);
    for (int v = 0; v < n; ++v)
      for (int d = 0; d < 2; ++d) b(2 * v + d) += eps * x(v, d);
    Eigen::SparseMatrix<double> A(2 * n, 2 * n);
    A.setFromTriplets(K.begin(), K.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
    const Eigen::VectorXd next = solver.solve(b);
    Eigen::MatrixX2d xn(n, 2);
    for (int v = 0; v < n; ++v) xn.row(v) << next(2 * v), next(2 * v + 1);
    const double step = (xn - x).cwiseAbs().maxCoeff();
    x = xn;
    if (step < stepTolerance) break;
  }
  return x * s;
}

}  // namespace ib::test
