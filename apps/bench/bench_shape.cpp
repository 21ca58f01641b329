// `inbetween bench shape`: how full-bodied and how evenly paced the inbetweens are, per scene and
// shape metric (../shared/shape-averaging.md): one JSON line per scene and metric.
#include "animation/even_spacing.h"
#include "bench/bench.h"

#include "core/error.h"
#include "interpolation/interpolator.h"
#include "multimesh/multimesh.h"
#include "pipeline/scene_multimesh.h"
#include "progress.h"
#include "scene/scene.h"

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench shape [--assets DIR | --scene FILE] [--metric shared|per_key|both] [--steps N]\n"
    "                             [--spacing weights|even] [--no-comesh] [--threads N]\n"
    "\n"
    "Walks every segment between consecutive marks of each scene's timeline in N equal steps of the\n"
    "weights (linear timing, no dynamics), solving each step from the one before, and measures the\n"
    "inbetweens. One JSON line per scene and metric: scene, metric, spacing, vertices, segments, steps,\n"
    "min_area_ratio (the smallest area of an inbetween over the area interpolated between its keys,\n"
    "sum_k w_k area(X_k)), worst_segment (where it is), max_snap (over segments, the larger change of\n"
    "the first and last step over the middle step's; 1 is even pacing; change = RMS vertex move),\n"
    "max_retime (with --spacing even: how far it moves a pose in time, in segment fractions),\n"
    "iterations_per_step, converged (share of steps), seconds (solving, the even-spacing samples included).\n"
    "\n"
    "  --assets DIR    folder of scenes, each DIR/NAME/scene.json (default: the bundled scenes)\n"
    "  --scene FILE    one scene instead\n"
    "  --metric M      shared, per_key or both (default both)\n"
    "  --steps N       steps per segment, 4..1000 (default 24)\n"
    "  --spacing S     weights: equal steps of the weights (default); even: equal steps of the path's\n"
    "                  even-spacing parameter (timeline \"spacing\": \"even\", docs/animation.md)\n"
    "  --no-comesh     measure the initial map (default: Comesh-optimized, as `inbetween mesh`)\n"
    "  --threads N     solver threads, 0 = all cores (default 0)\n";

double area(const Multimesh& mesh, const Eigen::MatrixX2d& x) {
  double sum = 0;
  for (const Triangle& t : mesh.triangles()) sum += 0.5 * edgeMatrix(x, t).determinant();
  return sum;
}

double rmsMove(const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b) {
  return std::sqrt((a - b).rowwise().squaredNorm().mean());
}

// The scene's marks joined by straight, linear segments (the path measured), evenly spaced when
// `even`: each segment's table from `solver`.
Timeline straightPaths(const Timeline& timeline, Interpolator& solver, bool even) {
  std::vector<TimelineSegment> segments(timeline.segments().size());
  for (TimelineSegment& segment : segments) segment.spacingKind = even ? SegmentSpacing::kEven : SegmentSpacing::kWeights;
  const Timeline straight(timeline.fps(), timeline.loops(), timeline.marks(), std::move(segments));
  return even ? evenSpacing(straight, solver) : straight;
}

nlohmann::json measure(const std::string& name, const Scene& scene, const Multimesh& mesh, ShapeMetric metric, int steps,
                       bool even, int threads) {
  InterpolationParams params = scene.interpolation;
  params.metric = metric;
  SolverOptions options;
  options.threads = threads;
  Interpolator solver(mesh, params, options);
  std::vector<double> keyArea(mesh.keyCount());
  for (int k = 0; k < mesh.keyCount(); ++k) keyArea[k] = area(mesh, mesh.keyPositions(k));
  const auto& marks = scene.timeline.marks();
  double minRatio = 1e300, maxSnap = 0, seconds = 0;
  int worst = -1, converged = 0, solved = 0;
  long iterations = 0;
  const auto started = std::chrono::steady_clock::now();
  const Timeline paths = straightPaths(scene.timeline, solver, even);
  // How far even spacing moves the poses in time: max |L(p_j) - p_j|, in segment fractions.
  double retime = 0;
  for (const TimelineSegment& segment : paths.segments())
    for (size_t j = 0; j < segment.spacing.size(); ++j)
      retime = std::max(retime, std::abs(segment.spacing[j] - static_cast<double>(j) / (segment.spacing.size() - 1)));
  for (size_t segment = 0; segment + 1 < marks.size(); ++segment) {
    const Eigen::VectorXd& a = marks[segment].weights;
    const Eigen::VectorXd& b = marks[segment + 1].weights;
    if ((a - b).cwiseAbs().maxCoeff() < 1e-12) continue;  // a hold
    std::vector<Eigen::MatrixX2d> x;
    for (int j = 0; j <= steps; ++j) {
      const double s = pathParameter(paths.segments()[segment], double(j) / steps);
      const Eigen::VectorXd w = (1 - s) * a + s * b;
      const InterpolationResult r = solver.solve(w, x.empty() ? nullptr : &x.back());
      iterations += r.iterations;
      converged += r.converged;
      ++solved;
      x.push_back(r.x);
      if (j == 0 || j == steps) continue;
      double interpolated = 0;
      for (Eigen::Index k = 0; k < w.size(); ++k) interpolated += w[k] * keyArea[k];
      const double ratio = area(mesh, r.x) / interpolated;
      if (ratio < minRatio) {
        minRatio = ratio;
        worst = static_cast<int>(segment);
      }
    }
    const double middle = rmsMove(x[steps / 2], x[steps / 2 + 1]);
    if (middle > 0) maxSnap = std::max(maxSnap, std::max(rmsMove(x[0], x[1]), rmsMove(x[steps - 1], x[steps])) / middle);
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return {{"scene", name},
          {"metric", metric == ShapeMetric::kShared ? "shared" : "per_key"},
          {"spacing", even ? "even" : "weights"},
          {"vertices", mesh.vertexCount()},
          {"segments", static_cast<int>(marks.size()) - 1},
          {"steps", steps},
          {"min_area_ratio", worst < 0 ? 1.0 : minRatio},
          {"worst_segment", worst},
          {"max_snap", maxSnap},
          {"max_retime", retime},
          {"iterations_per_step", solved ? static_cast<double>(iterations) / solved : 0.0},
          {"converged", solved ? static_cast<double>(converged) / solved : 1.0},
          {"seconds", seconds}};
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  std::vector<std::filesystem::path> scenes;
  if (a.has("scene")) {
    scenes.push_back(a.value("scene", ""));
  } else {
    const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("shape");
    scenes = benchScenes(assets, {}, "shape");
  }
  const std::string metricName = a.value("metric", "both");
  std::vector<ShapeMetric> metrics;
  if (metricName == "shared" || metricName == "both") metrics.push_back(ShapeMetric::kShared);
  if (metricName == "per_key" || metricName == "both") metrics.push_back(ShapeMetric::kPerKey);
  if (metrics.empty()) throw InputError("bench shape: --metric: '" + metricName + "' is not shared, per_key or both");
  const int steps = a.integer("steps", 24, 4, 1000);
  const int threads = a.integer("threads", 0, 0, cli::kMaxThreads);
  const std::string spacing = a.value("spacing", "weights");
  if (spacing != "weights" && spacing != "even") throw InputError("bench shape: --spacing: '" + spacing + "' is not weights or even");
  for (const auto& file : scenes) {
    const Scene scene = loadScene(file.string());
    const std::string name = file.filename() == "scene.json" ? file.parent_path().filename().string() : file.stem().string();
    cli::Progress progress;
    SceneMultimeshOptions meshOptions;
    meshOptions.useCache = false;  // from the drawings, as bench anim
    meshOptions.comesh = !a.flag("no-comesh");
    const auto built = sceneMultimesh(scene, meshOptions, [&](const std::string& stage, double f) { progress.update(name + ": " + stage, f); });
    progress.finish();
    for (ShapeMetric metric : metrics) output.printLine(measure(name, scene, *built.multimesh, metric, steps, spacing == "even", threads));
  }
}

}  // namespace

Benchmark shapeBenchmark() {
  return {"shape", "how full-bodied and evenly paced the inbetweens are, per shape metric", kUsage,
          {"assets", "scene", "metric", "steps", "spacing", "threads"}, {"no-comesh"}, run};
}

}  // namespace ib
