#include "linalg/cholesky_preconditioner.h"
#include "testkit/shape_generators.h"

#include <catch2/catch.hpp>

#include <Eigen/OrderingMethods>
#include <Eigen/Sparse>
#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

using namespace ib;

namespace {

// The graph Laplacian of a 40 x 30 grid plus 0.3 I (symmetric positive definite, both triangles
// stored), as the Sobolev preconditioner builds it.
Eigen::SparseMatrix<double> shiftedLaplacian() {
  const GridMesh grid = rectangleGrid(40, 30, 4, 3);
  const int n = static_cast<int>(grid.points.rows());
  std::vector<Eigen::Triplet<double>> entries;
  for (int v = 0; v < n; ++v) entries.emplace_back(v, v, 0.3);
  for (const Triangle& t : grid.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      entries.emplace_back(a, a, 0.5);
      entries.emplace_back(b, b, 0.5);
      entries.emplace_back(a, b, -0.5);
      entries.emplace_back(b, a, -0.5);
    }
  Eigen::SparseMatrix<double> H(n, n);
  H.setFromTriplets(entries.begin(), entries.end());
  return H;
}

// n x 2, entries uniform in [-1, 1].
Eigen::MatrixX2d randomRhs(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1, 1);
  Eigen::MatrixX2d b(n, 2);
  for (int i = 0; i < n; ++i) b.row(i) << value(random), value(random);
  return b;
}

// |H x - b| / |b| after solving H x = b with the factor.
double relativeResidual(const CholeskyPreconditioner& factor, const Eigen::SparseMatrix<double>& H,
                        const Eigen::MatrixX2d& b) {
  Eigen::MatrixX2d x = b;
  factor.solve(x);
  return (H * x - b).norm() / b.norm();
}

}  // namespace

TEST_CASE("cholesky preconditioner: solves to single precision with METIS's order and with any order given, on 1 and 2 threads") {
  const Eigen::SparseMatrix<double> H = shiftedLaplacian();
  const int n = static_cast<int>(H.rows());
  const Eigen::MatrixX2d b = randomRhs(n, 5);
  std::vector<int> shuffled(n), reversed(n);
  std::iota(shuffled.begin(), shuffled.end(), 0);
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(5));
  std::iota(reversed.rbegin(), reversed.rend(), 0);
  // The factor is single precision: about 1e-7 relative, times the condition number (below 30).
  const double tolerance = 1e-5;
  for (int threads : {1, 2}) {
    INFO(threads << " threads");
    CholeskyPreconditioner factor(threads);
    factor.factorize(H);
    CHECK(relativeResidual(factor, H, b) < tolerance);
    for (const std::vector<int>* order : {&shuffled, &reversed}) {
      factor.factorizeInOrder(H, *order);
      CHECK(relativeResidual(factor, H, b) < tolerance);
    }
    // Back to METIS's order after a given one.
    factor.factorize(H);
    CHECK(relativeResidual(factor, H, b) < tolerance);
  }
}

TEST_CASE("cholesky preconditioner: a refactorization with new values in the same pattern solves the new matrix") {
  const Eigen::SparseMatrix<double> H = shiftedLaplacian();
  const int n = static_cast<int>(H.rows());
  // The same pattern, other values: off-diagonals weighted by position, the diagonal kept dominant.
  Eigen::SparseMatrix<double> other = H;
  for (int j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(other, j); it; ++it)
      if (it.row() != it.col()) it.valueRef() *= 1.0 + ((it.row() + it.col()) % 7) / 7.0;
  for (int j = 0; j < n; ++j) other.coeffRef(j, j) = 0.3 - (other.col(j).sum() - other.coeff(j, j));
  const Eigen::MatrixX2d b = randomRhs(n, 8);
  for (int threads : {1, 2}) {
    INFO(threads << " threads");
    CholeskyPreconditioner factor(threads);
    factor.factorize(H);
    factor.factorize(other);
    CHECK(relativeResidual(factor, other, b) < 1e-5);
    CHECK(relativeResidual(factor, H, b) > 1e-2);  // it is the new matrix that is solved
  }
}

TEST_CASE("cholesky preconditioner: dropping small factor entries keeps fewer of them, still solves closely, the same on 1 and 2 threads") {
  const Eigen::SparseMatrix<double> H = shiftedLaplacian();
  const int n = static_cast<int>(H.rows());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd;
  Eigen::AMDOrdering<int>()(H, amd);
  const std::vector<int> order(amd.indices().data(), amd.indices().data() + n);
  const Eigen::MatrixX2d b = randomRhs(n, 9);
  CholeskyPreconditioner exact(1);
  exact.factorizeInOrder(H, order);
  Eigen::MatrixX2d solved[2];
  for (int threads : {1, 2}) {
    INFO(threads << " threads");
    CholeskyPreconditioner dropped(threads);
    dropped.setDropTolerance(1e-3);
    dropped.factorizeInOrder(H, order);
    CHECK(dropped.factorNonZeros() < 0.8 * exact.factorNonZeros());
    CHECK(relativeResidual(dropped, H, b) < 2e-2);
    CHECK(relativeResidual(dropped, H, b) > 1e-5);  // it is an approximation
    solved[threads - 1] = b;
    dropped.solve(solved[threads - 1]);
  }
  CHECK(solved[0] == solved[1]);
}

TEST_CASE("cholesky preconditioner: a given order that is not a permutation of the unknowns is refused") {
  const Eigen::SparseMatrix<double> H = shiftedLaplacian();
  const int n = static_cast<int>(H.rows());
  CholeskyPreconditioner factor(1);
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  CHECK_THROWS_AS(factor.factorizeInOrder(H, std::vector<int>(order.begin(), order.end() - 1)), std::invalid_argument);
  std::vector<int> repeated = order;
  repeated[7] = 3;
  CHECK_THROWS_AS(factor.factorizeInOrder(H, repeated), std::invalid_argument);
  std::vector<int> outside = order;
  outside[7] = n;
  CHECK_THROWS_AS(factor.factorizeInOrder(H, outside), std::invalid_argument);
  factor.factorizeInOrder(H, order);
  CHECK(factor.factorized());
}

TEST_CASE("cholesky preconditioner: numbered by its elimination plan, a matrix factors with METIS's fill, each thread's part contiguous, and solves the same") {
  const Eigen::SparseMatrix<double> H = shiftedLaplacian();
  const int n = static_cast<int>(H.rows());
  const Eigen::MatrixX2d b = randomRhs(n, 11);
  for (int threads : {1, 2, 3}) {
    INFO(threads << " threads");
    const EliminationPlan plan = planElimination(H, threads);
    REQUIRE(static_cast<int>(plan.partStart.size()) == threads + 1);
    CHECK(plan.partStart.front() == 0);
    CHECK(std::is_sorted(plan.partStart.begin(), plan.partStart.end()));
    CHECK(plan.partStart.back() <= n);
    std::vector<int> sorted = plan.order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    REQUIRE(sorted == identity);
    // Independent parts of about equal work: on a grid each holds a fair share of the unknowns.
    for (int p = 0; p < threads; ++p) CHECK(plan.partStart[p + 1] - plan.partStart[p] > n / (2 * threads));

    // H renumbered: unknown order[k] becomes k.
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(n);
    for (int k = 0; k < n; ++k) P.indices()[plan.order[k]] = k;
    const Eigen::SparseMatrix<double> ordered = P * H * P.transpose();
    CholeskyPreconditioner metis(threads), preordered(threads);
    metis.factorize(H);
    preordered.setPreordered(plan.partStart);
    preordered.factorize(ordered);
    CHECK(preordered.factorNonZeros() == metis.factorNonZeros());
    const Eigen::MatrixX2d orderedB = P * b;
    CHECK(relativeResidual(preordered, ordered, orderedB) < 1e-5);
    // A refactorization with the same pattern keeps working.
    preordered.factorize(ordered);
    Eigen::MatrixX2d x = orderedB, y = b;
    preordered.solve(x);
    metis.solve(y);
    CHECK((P.transpose() * x - y).norm() < 1e-5 * y.norm());
  }
}

TEST_CASE("cholesky preconditioner: a preordered matrix that couples two threads' parts is refused, not solved wrongly") {
  const Eigen::SparseMatrix<double> H = shiftedLaplacian();
  const int n = static_cast<int>(H.rows());
  const EliminationPlan plan = planElimination(H, 2);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(n);
  for (int k = 0; k < n; ++k) P.indices()[plan.order[k]] = k;
  Eigen::SparseMatrix<double> coupled = P * H * P.transpose();
  // One entry between the first unknown of part 0 and the first of part 1.
  const int a = plan.partStart[0], b = plan.partStart[1];
  coupled.coeffRef(a, b) = coupled.coeffRef(b, a) = -0.1;
  CholeskyPreconditioner factor(2);
  factor.setPreordered(plan.partStart);
  REQUIRE_THROWS_AS(factor.factorize(coupled), std::logic_error);
}

TEST_CASE("cholesky preconditioner: rank-one updates and downdates within H's pattern solve the modified matrix, and undo each other") {
  const Eigen::SparseMatrix<double> H = shiftedLaplacian();
  const int n = static_cast<int>(H.rows());
  const GridMesh grid = rectangleGrid(40, 30, 4, 3);
  const Eigen::MatrixX2d b = randomRhs(n, 13);
  // Ten vectors, each on the three corners of a triangle (coupled in H): H + sum v v^T.
  const Eigen::MatrixX2d entries = randomRhs(15, 14);
  std::vector<std::vector<int>> rows;
  std::vector<std::vector<double>> values;
  Eigen::SparseMatrix<double> modified = H;
  for (int k = 0; k < 10; ++k) {
    const Triangle& t = grid.triangles[(k * 97) % grid.triangles.size()];
    rows.push_back({t[0], t[1], t[2]});
    values.push_back({entries(k, 0), entries(k, 1), entries(k + 5, 0)});
    Eigen::SparseVector<double> v(n);
    for (int c = 0; c < 3; ++c) v.coeffRef(t[c]) += values.back()[c];
    modified += Eigen::SparseMatrix<double>(v * v.transpose());
  }
  const EliminationPlan plan = planElimination(H, 2);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(n);
  for (int k = 0; k < n; ++k) P.indices()[plan.order[k]] = k;
  for (bool preordered : {false, true}) {
    INFO((preordered ? "preordered by an elimination plan" : "METIS's order"));
    CholeskyPreconditioner factor(2);
    // In the plan's numbering rows are renumbered as the matrix is.
    const auto at = [&](int row) { return preordered ? P.indices()[row] : row; };
    const auto system = [&](const Eigen::SparseMatrix<double>& A) {
      return preordered ? Eigen::SparseMatrix<double>(P * A * P.transpose()) : A;
    };
    const Eigen::MatrixX2d rhs = preordered ? Eigen::MatrixX2d(P * b) : b;
    if (preordered) factor.setPreordered(plan.partStart);
    factor.factorize(system(H));
    for (size_t k = 0; k < rows.size(); ++k) {
      std::vector<int> r;
      for (int row : rows[k]) r.push_back(at(row));
      factor.rankOneUpdate(r, values[k], 1.0);
    }
    CHECK(relativeResidual(factor, system(modified), rhs) < 1e-5);
    CHECK(relativeResidual(factor, system(H), rhs) > 1e-3);  // the factor did change
    for (size_t k = rows.size(); k-- > 0;) {
      std::vector<int> r;
      for (int row : rows[k]) r.push_back(at(row));
      factor.rankOneUpdate(r, values[k], -1.0);
    }
    CHECK(relativeResidual(factor, system(H), rhs) < 1e-5);
  }
}

TEST_CASE("cholesky preconditioner: a rank-one update that would leave the pattern, a downdate past definiteness, a failed or a dropped factor is refused") {
  const Eigen::SparseMatrix<double> H = shiftedLaplacian();
  const int n = static_cast<int>(H.rows());
  const Eigen::MatrixX2d b = randomRhs(n, 17);
  CholeskyPreconditioner factor(1);
  factor.factorize(H);
  // Opposite corners of the grid are not coupled in H; the factor is left as it was.
  CHECK_THROWS_AS(factor.rankOneUpdate({0, n - 1}, {1.0, 1.0}, 1.0), std::logic_error);
  CHECK(relativeResidual(factor, H, b) < 1e-5);
  CHECK_THROWS_AS(factor.rankOneUpdate({0, n}, {1.0, 1.0}, 1.0), std::invalid_argument);
  CHECK(relativeResidual(factor, H, b) < 1e-5);
  // H_00 is below 9, so taking 9 e_0 e_0^T away leaves it indefinite.
  REQUIRE(H.coeff(0, 0) < 9);
  CHECK_THROWS_AS(factor.rankOneUpdate({0}, {3.0}, -1.0), std::runtime_error);
  // Nor is a factor whose last factorization failed updated.
  CholeskyPreconditioner failed(1);
  failed.factorize(H);
  Eigen::SparseMatrix<double> indefinite = H;
  indefinite.coeffRef(0, 0) = -1;
  CHECK_THROWS_AS(failed.factorize(indefinite), std::runtime_error);
  CHECK_THROWS_AS(failed.rankOneUpdate({0}, {1.0}, 1.0), std::logic_error);
  // A factor with dropped entries has no exact pattern to update.
  CholeskyPreconditioner dropped(1);
  dropped.setDropTolerance(1e-3);
  dropped.factorize(H);
  CHECK_THROWS_AS(dropped.rankOneUpdate({0}, {1.0}, 1.0), std::logic_error);
}
