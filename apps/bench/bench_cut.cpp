// `inbetween bench cut`: the interpolation solver through a cut letting go, with H's factor
// following the cohesive pairs by rank-one updates and without, one JSON line per case.
#include "bench/bench.h"

#include "interpolation/interpolator.h"
#include "progress.h"
#include "testkit/shape_generators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench cut [--sizes LIST] [--frames N] [--repeats N] [--threads N]\n"
    "\n"
    "Two squares glued along a seam of cohesive pairs in key 0 and apart in key 1, swept from\n"
    "w = (1, 0) to (0, 1), each frame warm-started from the last; the pairs let go on the way.\n"
    "One JSON line per (vertices, update_factor):\n"
    "  update_factor         true: H's factor follows pairs that engage or let go by rank-one\n"
    "                        updates (SolverOptions::updateFactor); false: H is refactorized after\n"
    "                        staleHeldIterations iterations with other pairs than its own\n"
    "  ms_per_frame          mean wall time of the sweep's frames (the cold start excluded)\n"
    "  hardest_frame         the frame with the most iterations (where most pairs let go), and its\n"
    "                        hardest_frame_iterations, hardest_frame_ms, hardest_frame_factorizations\n"
    "  iterations_per_frame, factorizations, factor_updates, unconverged_frames: over the sweep\n"
    "  steal_percent         CPU time a hypervisor gave to other guests during the case\n"
    "Times are medians over the repeats; the rest does not vary from run to run.\n"
    "\n"
    "  --sizes LIST    approximate vertex counts, e.g. 1k,10k,50k (default)\n"
    "  --frames N      frames in the sweep (default 50)\n"
    "  --repeats N     sweeps per case (default 3)\n"
    "  --threads N     threads (default: all cores)\n";

struct CutSweep {
  double msPerFrame = 0;
  int hardestFrame = 0, hardestIterations = -1, hardestFactorizations = 0;
  double hardestMs = 0;
  long iterations = 0;
  int factorizations = 0, updates = 0, unconverged = 0, threads = 0;
};

CutSweep sweep(const Multimesh& mesh, const SolverOptions& options, int frames) {
  Interpolator solver(mesh, InterpolationParams{}, options);
  InterpolationResult r = solver.solve(Eigen::Vector2d(1, 0));
  CutSweep out;
  out.threads = solver.threads();
  double total = 0;
  for (int k = 1; k <= frames; ++k) {
    const double s = double(k) / frames;
    r = solver.solve(Eigen::Vector2d(1 - s, s), &r.x);
    total += r.milliseconds;
    out.iterations += r.iterations;
    out.factorizations += r.factorizations;
    out.updates += r.factorUpdates;
    out.unconverged += !r.converged;
    if (r.iterations > out.hardestIterations) {
      out.hardestFrame = k;
      out.hardestIterations = r.iterations;
      out.hardestFactorizations = r.factorizations;
      out.hardestMs = r.milliseconds;
    }
  }
  out.msPerFrame = total / frames;
  return out;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t m = values.size() / 2;
  return values.size() % 2 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}

nlohmann::json benchCase(int vertices, bool update, int frames, int repeats, int threads, cli::Progress& progress) {
  const int side = std::max(3, static_cast<int>(std::lround(std::sqrt(vertices / 2.0))));
  const Multimesh mesh = gluedSquares(side, 1.0, 0.3);
  SolverOptions options;
  options.threads = threads;
  options.updateFactor = update;
  const StealMeter steal;
  std::vector<CutSweep> runs;
  std::vector<double> msPerFrame, hardestMs;
  for (int k = 0; k < repeats; ++k) {
    progress.update(std::to_string(mesh.vertexCount()) + " vertices, update_factor " + (update ? "on" : "off") +
                        ": sweep " + std::to_string(k + 1) + " of " + std::to_string(repeats),
                    double(k) / repeats);
    runs.push_back(sweep(mesh, options, frames));
    msPerFrame.push_back(runs.back().msPerFrame);
    hardestMs.push_back(runs.back().hardestMs);
  }
  const CutSweep& any = runs.front();
  nlohmann::json out = {{"vertices", mesh.vertexCount()},
                        {"pairs", side - 1},
                        {"frames", frames},
                        {"update_factor", update},
                        {"threads", any.threads},
                        {"ms_per_frame", median(msPerFrame)},
                        {"iterations_per_frame", double(any.iterations) / frames},
                        {"factorizations", any.factorizations},
                        {"factor_updates", any.updates},
                        {"unconverged_frames", any.unconverged},
                        {"hardest_frame", any.hardestFrame},
                        {"hardest_frame_iterations", any.hardestIterations},
                        {"hardest_frame_factorizations", any.hardestFactorizations},
                        {"hardest_frame_ms", median(hardestMs)}};
  steal.addTo(out);
  return out;
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::vector<int> sizes = cli::integerList(a.value("sizes", "1k,10k,50k"), "sizes", 18, 2000000);
  const int frames = a.integer("frames", 50, 1, 100000);
  const int repeats = a.integer("repeats", 3, 1, 100);
  const int threads = a.integer("threads", 0, 0, cli::kMaxThreads);
  for (int vertices : sizes)
    for (bool update : {true, false}) {
      cli::Progress progress;
      const nlohmann::json line = benchCase(vertices, update, frames, repeats, threads, progress);
      progress.finish();
      output.printLine(line);
    }
}

}  // namespace

Benchmark cutBenchmark() {
  return {"cut", "the solver through a cut letting go", kUsage, {"sizes", "frames", "repeats", "threads"}, {}, run};
}

}  // namespace ib
