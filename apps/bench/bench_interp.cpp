// `inbetween bench interp`: the interpolation solver on strips built in code, one JSON line per
// (vertices, keys) case.
#include "bench/bench.h"

#include "animation/warm_start.h"
#include "bench/contended_core.h"
#include "interpolation/interpolator.h"
#include "testkit/reference_arap.h"
#include "testkit/shape_generators.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench interp [--sizes LIST] [--keys LIST] [--frames N] [--repeats N] [--threads N]\n"
    "                              [--no-baseline] [--contended]\n"
    "\n"
    "Interpolation solver on strips built in code (rest, 180-degree bend, stretch, wave keys).\n"
    "One JSON line per (vertices, keys) case:\n"
    "  ms_per_iter         the sweep below per iteration, factorizations excluded: one accelerated\n"
    "                      iteration (local step + global solve) plus its share of each frame's\n"
    "                      setup and start evaluation and of rejected candidates (null if no\n"
    "                      frame needed an iteration)\n"
    "  iters_to_converge   mean iterations per warm-started frame to relative residual 1e-3\n"
    "  evaluations_per_frame\n"
    "                      mean local steps (energy and gradient) per frame: the start's, one per\n"
    "                      iteration and one per rejected accelerated candidate\n"
    "  ms_per_frame        mean wall time of those frames (each at a new w), factorizations included;\n"
    "                      each starts from the last two frames extrapolated (WarmStartPredictor)\n"
    "  iters_to_energy_1e-3 / plain_iters_to_energy_1e-3\n"
    "                      iterations from key 0's drawing (a far start) until the energy is within\n"
    "                      1e-3 of the optimum, accelerated vs plain local-global (exact matrix,\n"
    "                      no Anderson)\n"
    "  reference_ms_per_iter\n"
    "                      the machine's speed during the case: one serial single-key ARAP iteration\n"
    "                      in libigl's formulation (tests/testkit/reference_arap.h) on the same\n"
    "                      strip, ends pinned and bent 180 degrees, timed right after each sweep\n"
    "  iter_vs_reference   ms_per_iter / reference_ms_per_iter, paired per sweep (median)\n"
    "  steal_percent       share of all CPUs' time that a hypervisor gave to other guests during the\n"
    "                      sweeps and yardsticks (Linux /proc/stat; absent elsewhere). Above a few\n"
    "                      percent a vCPU was taken away mid-run: two-thread times then show the host\n"
    "                      more than the code\n"
    "  threads_used        mean threads the sweep's iterations ran on (the thread budget's choice:\n"
    "                      fewer than threads while other programs keep cores busy)\n"
    "  with --contended, also: one_thread_ms_per_frame, one_thread_ms_per_iter (the same sweeps on one\n"
    "                      thread, alternating with them) and vs_one_thread (ms_per_frame over\n"
    "                      one_thread_ms_per_frame)\n"
    "\n"
    "  --sizes LIST    approximate vertex counts, e.g. 1k,10k,100k (default)\n"
    "  --keys LIST     key counts, each 1..4 (default 2,4)\n"
    "  --frames N      frames in the warm-started sweep (default 24)\n"
    "  --repeats N     sweeps per case; times are their medians (default 3)\n"
    "  --threads N     threads (default: all cores)\n"
    "  --no-baseline   skip the plain local-global comparison (slow at 100k)\n"
    "  --contended     a busy process pinned to one core for the whole run (bench/contended_core.h);\n"
    "                  each sweep is also run on one thread, for comparison\n";

using Clock = std::chrono::steady_clock;
double millisecondsSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// The sweep's weights at s in [0, 1]: two keys go 0 -> 1; more keys blend n-way with every
// weight w_i(s) ~ 1 + cos(2 pi (s - i/m)), all positive most of the time.
Eigen::VectorXd sweepWeights(int keys, double s) {
  Eigen::VectorXd w(keys);
  if (keys == 1) {
    w(0) = 1;
  } else if (keys == 2) {
    w << 1 - s, s;
  } else {
    for (int i = 0; i < keys; ++i) w(i) = 1 + std::cos(2 * M_PI * (s - double(i) / keys));
    w /= w.sum();
  }
  return w;
}

// First iteration whose energy is within `gap` (relative) of optimum, or -1.
int iterationsToEnergy(const std::vector<double>& history, double optimum, double gap) {
  for (size_t k = 0; k < history.size(); ++k)
    if (history[k] - optimum <= gap * std::abs(optimum)) return static_cast<int>(k);
  return -1;
}

// One warm-started sweep of `frames` frames after a cold solve at s = 0.
struct Sweep {
  double msPerFrame = 0, msPerIter = 0, maxMs = 0, itersPerFrame = 0, evaluationsPerFrame = 0, firstSolveMs = 0,
         factorMs = 0;
  double referenceMsPerIter = 0;  // the yardstick, timed right after the sweep
  int factorizations = 0, unconverged = 0, threads = 0;
  double threadsUsed = 0;  // mean threads the frames' last iterations ran on
  long factorNonZeros = 0;
};

Sweep runSweep(const Multimesh& mesh, const InterpolationParams& params, const SolverOptions& options, int keys,
               int frames, const std::string& label) {
  Interpolator solver(mesh, params, options);
  Sweep out;
  const auto started = Clock::now();
  WarmStartPredictor warmStart;
  InterpolationResult previous = solver.solve(sweepWeights(keys, 0));
  warmStart.remember(sweepWeights(keys, 0), previous.x);
  out.firstSolveMs = millisecondsSince(started);
  double totalMs = 0, factorMs = 0;
  long iterations = 0, evaluations = 0;
  for (int f = 1; f <= frames; ++f) {
    showStatus(label + ": frame " + std::to_string(f) + "/" + std::to_string(frames));
    const Eigen::VectorXd w = sweepWeights(keys, double(f) / frames);
    const auto frameStarted = Clock::now();  // the frame as a player runs it: predict, then solve
    const auto start = warmStart.predict(w);
    previous = solver.solve(w, &*start);
    warmStart.remember(w, previous.x);
    const double frameMs = millisecondsSince(frameStarted);
    totalMs += frameMs;
    factorMs += previous.factorMilliseconds;
    out.maxMs = std::max(out.maxMs, frameMs);
    iterations += previous.iterations;
    evaluations += previous.evaluations;
    out.factorizations += previous.factorizations;
    out.unconverged += !previous.converged;
    out.threadsUsed += double(previous.threads) / frames;
  }
  out.msPerFrame = totalMs / frames;
  out.msPerIter = (totalMs - factorMs) / std::max(1L, iterations);
  out.itersPerFrame = double(iterations) / frames;
  out.evaluationsPerFrame = double(evaluations) / frames;
  out.factorMs = out.factorizations ? factorMs / out.factorizations : 0.0;
  out.threads = solver.threads();
  out.factorNonZeros = solver.factorNonZeros();
  return out;
}

// Vertices of a strip's two end columns: the smallest and the largest x.
std::vector<int> endColumns(const Eigen::MatrixX2d& rest) {
  const double left = rest.col(0).minCoeff(), right = rest.col(0).maxCoeff();
  const double slack = 1e-9 * (right - left);
  std::vector<int> ends;
  for (int v = 0; v < rest.rows(); ++v)
    if (rest(v, 0) < left + slack || rest(v, 0) > right - slack) ends.push_back(v);
  return ends;
}

// The given rows of x, in that order: rows.size() x 2.
Eigen::MatrixX2d rowsOf(const Eigen::MatrixX2d& x, const std::vector<int>& rows) {
  Eigen::MatrixX2d out(static_cast<int>(rows.size()), 2);
  for (size_t r = 0; r < rows.size(); ++r) out.row(r) = x.row(rows[r]);
  return out;
}

// The yardstick: single-key ARAP on the strip's rest shape with its two end columns pinned and
// bent 180 degrees, iterated `iterations` times from where the last call left it.
class Yardstick {
 public:
  explicit Yardstick(const Multimesh& mesh)
      : x_(mesh.keyPositions(0)),
        handles_(endColumns(x_)),
        arap_(x_, mesh.triangles(), handles_),
        handlePositions_(rowsOf(bendStrip(x_, M_PI), handles_)) {}
  double msPerIteration(int iterations) {
    const auto started = Clock::now();
    for (int k = 0; k < iterations; ++k) arap_.iterate(x_, handlePositions_);
    return millisecondsSince(started) / iterations;
  }

 private:
  Eigen::MatrixX2d x_;  // starts at the rest shape; each call goes on from where the last stopped
  std::vector<int> handles_;
  ReferenceArap arap_;
  Eigen::MatrixX2d handlePositions_;
};

template <class Get>
double median(std::vector<Sweep> runs, Get get) {
  std::sort(runs.begin(), runs.end(), [&](const Sweep& a, const Sweep& b) { return get(a) < get(b); });
  return get(runs[runs.size() / 2]);
}

nlohmann::json benchCase(int vertices, int keys, int frames, int repeats, int threads, bool baseline, bool contended) {
  const Multimesh mesh = benchmarkStrip(vertices, keys);
  InterpolationParams params;
  SolverOptions options;
  options.threads = threads;
  const std::string label = std::to_string(mesh.vertexCount()) + " vertices, " + std::to_string(keys) + " keys";
  const Eigen::VectorXd middle = keys == 2 ? sweepWeights(2, 0.5) : sweepWeights(keys, 0.3);

  // Timings are medians over repeated sweeps: a shared machine's other load shows up as noise.
  // Each sweep is followed by the yardstick, so that every sweep is paired with the machine's
  // speed at that moment.
  Yardstick yardstick(mesh);
  const int referenceIterations = std::max(5, 200000 / mesh.vertexCount());
  std::vector<Sweep> runs, oneThread;
  SolverOptions one = options;
  one.threads = 1;
  const StealMeter steal;
  std::optional<ContendedCore> busy;
  if (contended) busy.emplace();
  for (int r = 0; r < repeats; ++r) {
    runs.push_back(runSweep(mesh, params, options, keys, frames, label));
    if (contended) oneThread.push_back(runSweep(mesh, params, one, keys, frames, label + ", one thread"));
    showStatus(label + ": yardstick");
    runs.back().referenceMsPerIter = yardstick.msPerIteration(referenceIterations);
  }
  busy.reset();
  const Sweep& any = runs.front();
  nlohmann::json out = {{"vertices", mesh.vertexCount()},
                        {"keys", keys},
                        {"ms_per_iter", median(runs, [](const Sweep& s) { return s.msPerIter; })},
                        {"iters_to_converge", any.itersPerFrame},
                        {"evaluations_per_frame", any.evaluationsPerFrame},
                        {"ms_per_frame", median(runs, [](const Sweep& s) { return s.msPerFrame; })},
                        {"threads", any.threads},
                        {"frames", frames},
                        {"repeats", repeats},
                        {"ms_per_frame_max", median(runs, [](const Sweep& s) { return s.maxMs; })},
                        {"factorizations", any.factorizations},
                        {"ms_per_factorization", median(runs, [](const Sweep& s) { return s.factorMs; })},
                        {"unconverged_frames", any.unconverged},
                        {"first_solve_ms", median(runs, [](const Sweep& s) { return s.firstSolveMs; })},
                        {"factor_nonzeros", any.factorNonZeros},
                        {"reference_ms_per_iter", median(runs, [](const Sweep& s) { return s.referenceMsPerIter; })},
                        {"iter_vs_reference",
                         median(runs, [](const Sweep& s) { return s.msPerIter / s.referenceMsPerIter; })}};
  out["threads_used"] = median(runs, [](const Sweep& s) { return s.threadsUsed; });
  if (contended) {
    const double single = median(oneThread, [](const Sweep& s) { return s.msPerFrame; });
    out["contended"] = true;
    out["one_thread_ms_per_frame"] = single;
    out["one_thread_ms_per_iter"] = median(oneThread, [](const Sweep& s) { return s.msPerIter; });
    out["vs_one_thread"] = out["ms_per_frame"].get<double>() / single;
  }
  if (any.itersPerFrame == 0) {  // one key: every frame is the key itself, there is no iteration to time
    out["ms_per_iter"] = nullptr;
    out["iter_vs_reference"] = nullptr;
  }
  steal.addTo(out);  // the sweeps and yardsticks only, not the baseline below

  if (baseline) {
    showStatus(label + ": optimum and plain local-global baseline");
    SolverOptions tight = options;
    tight.relativeTolerance = 1e-12;
    tight.maxIterations = 2000;
    const Eigen::MatrixX2d farStart = mesh.keyPositions(0);
    const InterpolationResult accelerated = Interpolator(mesh, params, tight).solve(middle, &farStart);
    SolverOptions plainOptions = tight;
    plainOptions.andersonDepth = 0;
    plainOptions.refactorDistance = 0;
    plainOptions.maxIterations = vertices > 50000 ? 1500 : 4000;
    const InterpolationResult plain = Interpolator(mesh, params, plainOptions).solve(middle, &farStart);
    const double optimum = std::min(accelerated.energy, plain.energy);
    const int fast = iterationsToEnergy(accelerated.energyHistory, optimum, 1e-3);
    const int slow = iterationsToEnergy(plain.energyHistory, optimum, 1e-3);
    out["iters_to_energy_1e-3"] = fast;
    out["plain_iters_to_energy_1e-3"] = slow;  // -1: not reached within the cap
    out["plain_iteration_cap"] = plainOptions.maxIterations;
    if (fast > 0 && slow > 0) out["iteration_ratio"] = double(slow) / fast;
  }
  showStatus("");
  return out;
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::vector<int> sizes = cli::integerList(a.value("sizes", "1k,10k,100k"), "sizes", 16, 2000000);
  const std::vector<int> keyCounts = cli::integerList(a.value("keys", "2,4"), "keys", 1, 4);
  const int frames = a.integer("frames", 24, 1, 100000);
  const int repeats = a.integer("repeats", 3, 1, 100);
  const int threads = a.integer("threads", 0, 0, cli::kMaxThreads);
  for (int vertices : sizes)
    for (int keys : keyCounts)
      output.printLine(benchCase(vertices, keys, frames, repeats, threads, !a.flag("no-baseline"), a.flag("contended")));
}

}  // namespace

Benchmark interpBenchmark() {
  return {"interp", "the interpolation solver on strips built in code", kUsage,
          {"sizes", "keys", "frames", "repeats", "threads"}, {"no-baseline", "contended"}, run};
}

}  // namespace ib
