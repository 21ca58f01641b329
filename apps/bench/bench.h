// `inbetween bench CASE`: benchmarks that print one JSON object per case on its own line. Each
// bench_CASE.cpp holds one measurement and describes it as a Benchmark; runBench (bench.cpp) does
// the rest once for all: picks the case, answers --help, parses the options, prints the lines.
#pragma once

#include "cli.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ib {

// Prints a benchmark's lines on stdout, each one JSON object, flushed at once.
class BenchOutput {
 public:
  explicit BenchOutput(std::string bench) : bench_(std::move(bench)) {}
  // Adds the fields every line has, "bench" (the case) and "arch" (the instruction set the command
  // was built for, INBETWEEN_ARCH: x86-64-v3, native or default), then prints `line`.
  void printLine(nlohmann::json line) const;

 private:
  std::string bench_;
};

struct Benchmark {
  const char* name;                       // the CASE word, e.g. "interp"
  const char* summary;                    // one line for `inbetween bench --help`
  const char* usage;                      // `inbetween bench CASE --help`
  std::vector<std::string> valueOptions;  // options that take a value (cli::Arguments)
  std::vector<std::string> flagOptions;   // options that take none
  // Measures and prints one line per case; throws InputError for a bad option value.
  void (*run)(const cli::Arguments& arguments, const BenchOutput& output);
};

// One per bench_CASE.cpp.
Benchmark interpBenchmark();
Benchmark comeshBenchmark();
Benchmark animBenchmark();
Benchmark meshBenchmark();
#ifdef INBETWEEN_WITH_ENGINE
Benchmark renderBenchmark();
Benchmark playBenchmark();
Benchmark editBenchmark();
Benchmark ghostBenchmark();
Benchmark keysBenchmark();
#endif
Benchmark cutBenchmark();
Benchmark popsBenchmark();
Benchmark shapeBenchmark();
Benchmark examplesBenchmark();

// args: the words after "bench". Returns the exit code; throws InputError on bad arguments.
int runBench(const std::vector<std::string>& args);

// CPU time a hypervisor gave to other guests while this one wanted to run, from Linux's
// /proc/stat (all CPUs); nothing where it is unavailable.
class StealMeter {
 public:
  StealMeter();  // starts measuring
  // Adds "steal_percent": the stolen share of all CPUs' time since construction, in percent.
  void addTo(nlohmann::json& line) const;

 private:
  struct Ticks {
    long long steal = 0, total = 0;  // clock ticks since boot
  };
  static std::optional<Ticks> read();
  std::optional<Ticks> start_;
};

// The bundled scenes, for the benchmarks' default --assets: share/inbetween/assets beside the
// program's folder (<prefix>/bin -> <prefix>/share/inbetween/assets when installed; the build
// tree links the source tree's assets/ there). InputError when there is none, saying to give
// --assets.
std::filesystem::path bundledAssets(const std::string& bench);

// The scene files NAME/scene.json in `assets`, sorted by NAME; with `only` non-empty just those
// NAMEs. InputError when `assets` is no folder, holds no scene, or a name in `only` is none of
// them (naming the nearest and every scene there is).
std::vector<std::filesystem::path> benchScenes(const std::filesystem::path& assets, const std::vector<std::string>& only,
                                               const std::string& bench);

// --edge-length PX of the window benchmarks (play, edit): 0 when not given; InputError outside [0.5, 1000].
double edgeLengthOption(const cli::Arguments& arguments);
// A copy of the scene's folder in the temporary folder with `edge_length` replaced (a larger mesh
// of the same drawings).
std::filesystem::path sceneWithEdgeLength(const std::filesystem::path& file, double edgeLength, const std::string& bench);

// `scene`'s multimesh built from its drawings as `inbetween mesh` builds it, never from a cache (a
// .ibmesh left beside the scene must not change the figures), on `threads` solver threads (0: all
// cores); its stages shown on `progress` as `name: stage`, over the first `share` of the line.
SceneMultimesh builtFromDrawings(const Scene& scene, int threads, const std::string& name, cli::Progress& progress, double share);

// One line of status on stderr, rewritten in place, when stderr is a terminal; "" clears it.
void showStatus(const std::string& text);

}  // namespace ib
