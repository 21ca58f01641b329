#include "linalg/elimination_plan.h"

#include <iostream>  // Eigen's MetisSupport reports through std::cerr without including it
#include <Eigen/MetisSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <stdexcept>

namespace ib {

EliminationSchedule scheduleSubtrees(const std::vector<int>& parent, const std::vector<long>& entries, int threads) {
  const int n = static_cast<int>(parent.size());
  std::vector<long> weight = entries;  // nonzeros in each subtree, once the loop has passed it
  std::vector<std::vector<int>> children(n);
  std::vector<int> roots;
  for (int j = 0; j < n; ++j) {  // a child comes before its parent
    if (parent[j] >= 0) {
      weight[parent[j]] += weight[j];
      children[parent[j]].push_back(j);
    } else {
      roots.push_back(j);
    }
  }
  // Walk down from the root while one child carries almost all the work: that chain is the top
  // separator. Below it, subtrees are independent and go to threads by greedy balancing.
  EliminationSchedule schedule;
  std::vector<int> level = roots;
  while (level.size() == 1 && !children[level[0]].empty()) {
    schedule.top.push_back(level[0]);
    level = children[level[0]];
  }
  // With fewer subtrees than threads, the heaviest subtree's root joins the top as well, and its
  // children the level, until every thread can have one.
  while (static_cast<int>(level.size()) < threads) {
    auto heaviest = level.end();
    for (auto it = level.begin(); it != level.end(); ++it)
      if (!children[*it].empty() && (heaviest == level.end() || weight[*it] > weight[*heaviest])) heaviest = it;
    if (heaviest == level.end()) break;
    const int root = *heaviest;
    level.erase(heaviest);
    schedule.top.push_back(root);
    level.insert(level.end(), children[root].begin(), children[root].end());
  }
  std::stable_sort(level.begin(), level.end(), [&](int a, int b) { return weight[a] > weight[b]; });
  schedule.part.assign(threads, {});
  std::vector<long> load(threads, 0);
  std::vector<int> owner(n, -1), stack;
  for (int root : level) {
    const int t = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[t] += weight[root];
    stack = {root};
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      owner[v] = t;
      for (int c : children[v]) stack.push_back(c);
    }
  }
  for (int j = 0; j < n; ++j)
    if (owner[j] >= 0) schedule.part[owner[j]].push_back(j);
  std::sort(schedule.top.begin(), schedule.top.end());  // a parent comes after its children
  return schedule;
}

namespace {

// The symbolic analysis alone (METIS order, elimination tree, column counts), without the
// numeric factorization: Eigen keeps the tree and counts in protected members.
class SymbolicAnalysis
    : public Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::MetisOrdering<int>> {
 public:
  explicit SymbolicAnalysis(const Eigen::SparseMatrix<double>& H) { analyzePattern(H); }
  std::vector<int> parent() const { return {m_parent.data(), m_parent.data() + m_parent.size()}; }
  // Nonzeros of each column of L, the diagonal included.
  std::vector<long> entries() const {
    std::vector<long> count(m_nonZerosPerCol.data(), m_nonZerosPerCol.data() + m_nonZerosPerCol.size());
    for (long& c : count) ++c;
    return count;
  }
};

}  // namespace

EliminationPlan planElimination(const Eigen::SparseMatrix<double>& H, int threads) {
  const SymbolicAnalysis analysis(H);
  if (analysis.info() != Eigen::Success) throw std::runtime_error("elimination plan: the pattern cannot be analyzed");
  const int n = static_cast<int>(H.rows());
  const int* perm = analysis.permutationP().indices().data();  // row i of H is row perm[i] of L's system
  std::vector<int> unknownAt(n);
  for (int i = 0; i < n; ++i) unknownAt[perm[i]] = i;
  // A topological order of the same elimination tree, so the factor has the same fill.
  const EliminationSchedule schedule = scheduleSubtrees(analysis.parent(), analysis.entries(), std::max(1, threads));
  EliminationPlan plan;
  plan.partStart.push_back(0);
  for (const auto& part : schedule.part) {
    for (int j : part) plan.order.push_back(unknownAt[j]);
    plan.partStart.push_back(static_cast<int>(plan.order.size()));
  }
  for (int j : schedule.top) plan.order.push_back(unknownAt[j]);
  return plan;
}

}  // namespace ib
