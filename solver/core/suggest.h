// "Did you mean": the known name nearest a mistyped one, for messages about names (a parameter,
// a field, a key, a feature).
#pragma once

#include <string>
#include <vector>

namespace ib {

// Edits (insert, delete, substitute, swap two neighbours) between a and b, case-insensitive.
int editDistance(const std::string& a, const std::string& b);

// ` (did you mean "NAME"?)` for the candidate nearest `word` when it is a plausible typo (at most
// max(1, length / 3) edits, or `word` differs from it only in case), else "".
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace ib
