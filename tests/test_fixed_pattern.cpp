#include "linalg/fixed_pattern.h"

#include <catch2/catch.hpp>

#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace ib;

namespace {

// What Eigen makes of the same entries: setFromTriplets, then the lower triangle.
Eigen::SparseMatrix<double> eigenLower(int n, const std::vector<std::pair<int, int>>& at, const std::vector<double>& value) {
  std::vector<Eigen::Triplet<double>> entries;
  for (size_t k = 0; k < at.size(); ++k) entries.emplace_back(at[k].first, at[k].second, value[k]);
  Eigen::SparseMatrix<double> full(n, n);
  full.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseMatrix<double> lower = full.triangularView<Eigen::Lower>();
  lower.makeCompressed();
  return lower;
}

}  // namespace

TEST_CASE("fixed pattern assembly: every assembly equals setFromTriplets' lower triangle bit for bit") {
  const int n = 40;
  std::mt19937 random(11);
  std::uniform_int_distribution<int> index(0, n - 1);
  std::uniform_real_distribution<double> number(-1, 1);
  std::vector<std::pair<int, int>> at;
  for (int k = 0; k < 600; ++k) at.emplace_back(index(random), index(random));  // many repeats
  for (int v = 0; v < n; ++v) at.emplace_back(v, v);
  FixedPatternAssembly assembly(n);
  for (int round = 0; round < 3; ++round) {
    INFO("assembly " << round);
    std::vector<double> value;
    for (size_t k = 0; k < at.size(); ++k) value.push_back(number(random));
    assembly.begin();
    for (size_t k = 0; k < at.size(); ++k) assembly.add(at[k].first, at[k].second, value[k]);
    const Eigen::SparseMatrix<double>& mine = assembly.matrix();
    const Eigen::SparseMatrix<double> expected = eigenLower(n, at, value);
    REQUIRE(mine.nonZeros() == expected.nonZeros());
    for (int j = 0; j <= n; ++j) REQUIRE(mine.outerIndexPtr()[j] == expected.outerIndexPtr()[j]);
    for (Eigen::Index e = 0; e < mine.nonZeros(); ++e) {
      REQUIRE(mine.innerIndexPtr()[e] == expected.innerIndexPtr()[e]);
      REQUIRE(mine.valuePtr()[e] == expected.valuePtr()[e]);  // summed in the same order
    }
  }
}

TEST_CASE("fixed pattern assembly: entries in another order or number than the first assembly's are refused") {
  FixedPatternAssembly assembly(3);
  assembly.begin();
  assembly.add(0, 0, 1);
  assembly.add(1, 0, 2);
  assembly.add(2, 2, 3);
  assembly.matrix();
  assembly.begin();
  assembly.add(0, 0, 1);
  CHECK_THROWS_AS(assembly.add(2, 2, 3), std::logic_error);
  assembly.begin();
  assembly.add(0, 0, 1);
  assembly.add(1, 0, 2);
  CHECK_THROWS_AS(assembly.matrix(), std::logic_error);
  assembly.begin();
  assembly.add(0, 0, 1);
  assembly.add(1, 0, 2);
  assembly.add(2, 2, 3);
  CHECK_THROWS_AS(assembly.add(2, 1, 4), std::logic_error);
}
