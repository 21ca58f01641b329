// `inbetween bench CASE`: benchmarks that print one JSON object per case on its own line.
#pragma once

#include <optional>
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

// `inbetween bench cut ...` (bench_cut.cpp): args after "cut".
int runBenchCut(const std::vector<std::string>& args);

// CPU time of all CPUs since boot, in clock ticks, from Linux's /proc/stat; steal is time a
// hypervisor gave to other guests while this one wanted to run. Empty where unavailable.
struct CpuTicks {
  long long steal = 0, total = 0;
};
std::optional<CpuTicks> cpuTicks();

// Percentage of the CPU time between two readings that was stolen; empty without both.
std::optional<double> stealPercent(const std::optional<CpuTicks>& before, const std::optional<CpuTicks>& after);

}  // namespace ib
