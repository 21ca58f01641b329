// inbetween-bench: the benchmarks, run as `inbetween bench CASE ...` (which hands over to this
// program) or directly. Exit codes as inbetween's: 0 success, 2 bad input, 1 internal error.
#include "bench/bench.h"

#include "core/error.h"

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  try {
    return ib::runBench(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const ib::InputError& e) {
    std::fprintf(stderr, "inbetween: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inbetween: internal error: %s\n", e.what());
    return 1;
  } catch (...) {
    std::fprintf(stderr, "inbetween: internal error\n");
    return 1;
  }
}
