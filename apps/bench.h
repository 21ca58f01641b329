// `inbetween bench CASE`: benchmarks that print one JSON object per case on its own line.
#pragma once

#include <string>
#include <vector>

namespace ib {

// args: the words after "bench". Returns the exit code; throws InputError on bad arguments.
int runBench(const std::vector<std::string>& args);

// `inbetween bench comesh ...` (bench_comesh.cpp): args after "comesh".
int runBenchComesh(const std::vector<std::string>& args);

// `inbetween bench anim ...` (bench_anim.cpp): args after "anim".
int runBenchAnim(const std::vector<std::string>& args);

// `inbetween bench render ...` (bench_render.cpp): args after "render".
int runBenchRender(const std::vector<std::string>& args);

}  // namespace ib
