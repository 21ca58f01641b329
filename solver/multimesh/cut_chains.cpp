#include "multimesh/cut_chains.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <stdexcept>

namespace ib {

namespace {

std::array<int, 4> idOf(const CohesivePair& p) { return {p.a, p.b, p.c, p.d}; }

}  // namespace

int CutChains::indexOf(const CohesivePair& pair) const {
  const auto at = std::lower_bound(pairs.begin(), pairs.end(), pair,
                                   [](const CohesivePair& x, const CohesivePair& y) { return idOf(x) < idOf(y); });
  if (at == pairs.end() || idOf(*at) != idOf(pair)) throw std::invalid_argument("cut chains: not a cohesive pair of the multimesh");
  return static_cast<int>(at - pairs.begin());
}

CutChains cutChains(const Multimesh& mesh) {
  CutChains out;
  const int m = mesh.keyCount();
  std::map<std::array<int, 4>, std::vector<char>> closing;
  for (int k = 0; k < m; ++k)
    for (const CohesivePair& p : mesh.cohesivePairs(k)) {
      std::vector<char>& keys = closing[idOf(p)];
      keys.resize(static_cast<size_t>(m), 0);
      keys[k] = 1;
    }
  for (const auto& [id, keys] : closing) {
    out.pairs.push_back({id[0], id[1], id[2], id[3]});
    out.closedIn.push_back(keys);
  }
  // Union-find over shared vertices, among pairs closed in the same keys.
  std::vector<int> parent(out.pairs.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int p) {
    while (parent[p] != p) p = parent[p] = parent[parent[p]];
    return p;
  };
  std::map<int, int> firstAt;  // vertex -> a pair using it
  for (size_t p = 0; p < out.pairs.size(); ++p)
    for (int v : idOf(out.pairs[p])) {
      const auto [it, fresh] = firstAt.emplace(v, static_cast<int>(p));
      if (!fresh && out.closedIn[it->second] == out.closedIn[p]) parent[root(static_cast<int>(p))] = root(it->second);
    }
  std::map<int, int> chainOfRoot;
  for (size_t p = 0; p < out.pairs.size(); ++p) {
    const auto [it, fresh] = chainOfRoot.emplace(root(static_cast<int>(p)), static_cast<int>(chainOfRoot.size()));
    out.chainOf.push_back(it->second);
  }
  out.chains = static_cast<int>(chainOfRoot.size());
  return out;
}

}  // namespace ib
