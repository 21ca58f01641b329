// `inbetween bench CASE ...`: the benchmarks are a program of their own, inbetween-bench, beside
// this one (it links the test kit's yardsticks and shape generators, which the shipping command
// does not carry); this runs it in this process's place.
#pragma once

#include <string>
#include <vector>

namespace ib {

// Replaces this process with inbetween-bench from the same folder, given `args`; returns only
// by throwing: InputError when it is not there (build or install it), std::runtime_error when it
// is there but cannot be run, naming the path.
[[noreturn]] void runBenchProgram(const std::vector<std::string>& args);

}  // namespace ib
