// A multimesh's cuts as chains of cohesive pairs: its distinct pairs (a pair that several keys
// close counted once, with the keys that close it), grouped into chains of pairs that share a
// vertex and are closed in the same keys: one cut's pairs, end to end. The gap pull turns a chain
// as one, the renderer inks a chain with one line, and under tau a chain lets go as one.
#pragma once

#include "multimesh/multimesh.h"

#include <vector>

namespace ib {

struct CutChains {
  std::vector<CohesivePair> pairs;          // distinct pairs, in (a, b, c, d) order
  std::vector<std::vector<char>> closedIn;  // [pair][key]: 1 where the key closes it
  std::vector<int> chainOf;                 // [pair]: its chain, numbered in order of first pair
  int chains = 0;
  // The index into pairs of a pair of some key's cohesivePairs.
  int indexOf(const CohesivePair& pair) const;
};

CutChains cutChains(const Multimesh& mesh);

}  // namespace ib
