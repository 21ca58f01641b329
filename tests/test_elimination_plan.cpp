#include "linalg/elimination_plan.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

using namespace ib;

namespace {

// Checks what the solves rely on: every column is in exactly one part or in the top, a part's
// columns have their parents in the same part or in the top (so parts never wait for each
// other), the top's columns have their parents in the top, and every list is ascending.
void checkSchedule(const EliminationSchedule& schedule, const std::vector<int>& parent, int threads) {
  const int n = static_cast<int>(parent.size());
  REQUIRE(static_cast<int>(schedule.part.size()) == threads);
  constexpr int kTop = -2, kNone = -1;
  std::vector<int> owner(n, kNone);
  for (int p = 0; p < threads; ++p) {
    CHECK(std::is_sorted(schedule.part[p].begin(), schedule.part[p].end()));
    for (int j : schedule.part[p]) {
      REQUIRE(owner[j] == kNone);
      owner[j] = p;
    }
  }
  CHECK(std::is_sorted(schedule.top.begin(), schedule.top.end()));
  for (int j : schedule.top) {
    REQUIRE(owner[j] == kNone);
    owner[j] = kTop;
  }
  for (int j = 0; j < n; ++j) {
    INFO("column " << j);
    REQUIRE(owner[j] != kNone);
    if (parent[j] < 0) continue;
    const int up = owner[parent[j]];
    if (owner[j] == kTop)
      CHECK(up == kTop);
    else
      CHECK((up == owner[j] || up == kTop));
  }
}

// A complete binary tree of 2^depth - 1 nodes numbered in post-order (children before parents).
std::vector<int> completeBinaryTree(int depth) {
  std::vector<int> parent;
  // Returns the subtree's root after numbering it.
  const auto build = [&](auto&& self, int levels) -> int {
    if (levels == 0) return -1;
    const int left = self(self, levels - 1), right = self(self, levels - 1);
    const int root = static_cast<int>(parent.size());
    parent.push_back(-1);
    if (left >= 0) parent[left] = parent[right] = root;
    return root;
  };
  build(build, depth);
  return parent;
}

}  // namespace

TEST_CASE("elimination schedule: on random forests every column is in one part or the top and no part waits for another") {
  std::mt19937 random(17);
  for (int n : {1, 2, 7, 100, 2000}) {
    for (int trial = 0; trial < 5; ++trial) {
      // parent[j] > j, or a root with probability 1/20.
      std::vector<int> parent(n, -1);
      std::vector<long> entries(n);
      for (int j = 0; j < n; ++j) {
        if (j + 1 < n && random() % 20 != 0) parent[j] = j + 1 + static_cast<int>(random() % std::min(n - j - 1, 8));
        entries[j] = 1 + static_cast<long>(random() % 20);
      }
      for (int threads : {1, 2, 3, 4}) {
        INFO(n << " columns, trial " << trial << ", " << threads << " threads");
        checkSchedule(scheduleSubtrees(parent, entries, threads), parent, threads);
      }
    }
  }
}

TEST_CASE("elimination schedule: a complete binary tree of equal weights splits into equal parts under a small top") {
  const int depth = 8;  // 255 nodes
  const std::vector<int> parent = completeBinaryTree(depth);
  const std::vector<long> entries(parent.size(), 1);
  for (int threads : {2, 4}) {
    INFO(threads << " threads");
    const EliminationSchedule schedule = scheduleSubtrees(parent, entries, threads);
    checkSchedule(schedule, parent, threads);
    // 2 threads: the root on top and one 127-node subtree each; 4 threads: the root and its two
    // children on top and one 63-node subtree each.
    CHECK(static_cast<int>(schedule.top.size()) == threads - 1);
    for (const auto& part : schedule.part) CHECK(static_cast<int>(part.size()) == (1 << (depth - threads / 2)) - 1);
  }
}

TEST_CASE("elimination schedule: a tree that never branches goes to the top, its leaf to one part") {
  const int n = 50;
  std::vector<int> parent(n);
  for (int j = 0; j < n; ++j) parent[j] = j + 1 < n ? j + 1 : -1;
  const EliminationSchedule schedule = scheduleSubtrees(parent, std::vector<long>(n, 3), 2);
  checkSchedule(schedule, parent, 2);
  CHECK(static_cast<int>(schedule.top.size()) == n - 1);
  CHECK(schedule.part[0] == std::vector<int>{0});
  CHECK(schedule.part[1].empty());
}
