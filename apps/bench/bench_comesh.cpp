// `inbetween bench comesh`: Comesh Optimization on bundled scenes, one JSON line per case.
#include "bench/bench.h"

#include "comesh/comesh.h"
#include "meshing/multimesh_builder.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench comesh [--sizes LIST] [--keys LIST] [--assets DIR]\n"
    "\n"
    "Comesh Optimization (paper Algorithm 1, fixed parameters) on bundled scenes. One JSON line per\n"
    "case: vertices_in/out, keys, outer, inner, flips/splits/collapses and their seconds, seconds\n"
    "(Comesh alone), build_seconds (tracing, meshing and the initial map, not included) and\n"
    "energy_in/out (eq. 8 before and after, px^2).\n"
    "\n"
    "  --sizes LIST   approximate vertex counts for square-hexagon (default 300,1k,17k,100k)\n"
    "  --keys LIST    key counts taken from star-sequence's 16 keys (default 2,4,8,16)\n"
    "  --assets DIR   folder holding square-hexagon/ and star-sequence/ (default: the source tree's\n"
    "                 assets/)\n";

using Clock = std::chrono::steady_clock;

nlohmann::json runCase(Scene scene, const std::string& label) {
  showStatus(label + ": building the initial map");
  const auto started = Clock::now();
  const BuiltScene built = buildMultimesh(scene, MultimeshBuildOptions{});
  const double buildSeconds = std::chrono::duration<double>(Clock::now() - started).count();
  ComeshOptions options;
  options.progress = [&](int outer, double energy) {
    char text[128];
    std::snprintf(text, sizeof text, "%s: outer iteration %d, energy %.6g", label.c_str(), outer, energy);
    showStatus(text);
  };
  ComeshReport r;
  comeshOptimize(*built.multimesh, &built.boundary, options, &r);
  showStatus("");
  return {{"scene", label},
          {"vertices_in", r.verticesIn}, {"vertices_out", r.verticesOut},
          {"keys", r.keys},              {"outer", r.outerIterations},
          {"inner", r.innerIterations},  {"flips", r.remesh.flips},
          {"splits", r.remesh.splits},   {"collapses", r.remesh.collapses},
          {"flip_seconds", r.remesh.flipSeconds}, {"split_seconds", r.remesh.splitSeconds},
          {"collapse_seconds", r.remesh.collapseSeconds}, {"seconds", r.seconds},
          {"build_seconds", buildSeconds}, {"energy_in", r.energyIn}, {"energy_out", r.energyOut}};
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::vector<int> sizes = cli::integerList(a.value("sizes", "300,1k,17k,100k"), "sizes", 50, 1000000);
  const std::vector<int> keyCounts = cli::integerList(a.value("keys", "2,4,8,16"), "keys", 2, 16);
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("comesh");

  const Scene squareHexagon = loadScene((assets / "square-hexagon" / "scene.json").string());
  // Vertex count goes with 1 / edge length^2: calibrated on the bundled scene at 300-17k vertices.
  const double referenceVertices = 365;
  for (int vertices : sizes) {
    Scene scene = squareHexagon;
    scene.edgeLength = squareHexagon.edgeLength * std::sqrt(referenceVertices / vertices);
    output.printLine(runCase(scene, "square-hexagon@" + std::to_string(vertices)));
  }
  const Scene sequence = loadScene((assets / "star-sequence" / "scene.json").string());
  for (int keys : keyCounts) {
    Scene scene = sequence;
    scene.keys.resize(keys);
    output.printLine(runCase(scene, "star-sequence@" + std::to_string(keys)));
  }
}

}  // namespace

Benchmark comeshBenchmark() {
  return {"comesh", "Comesh Optimization on bundled scenes", kUsage, {"sizes", "keys", "assets"}, {}, run};
}

}  // namespace ib
