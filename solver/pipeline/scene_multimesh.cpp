#include "pipeline/scene_multimesh.h"

#include "comesh/comesh.h"
#include "core/error.h"
#include "core/thread_budget.h"
#include "meshing/multimesh_builder.h"
#include "meshing/stiffness_paint.h"
#include "multimesh/mesh_quality.h"
#include "multimesh/multimesh_io.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>

namespace ib {

namespace fs = std::filesystem;

SceneMultimesh::SceneMultimesh() = default;
SceneMultimesh::~SceneMultimesh() = default;
SceneMultimesh::SceneMultimesh(SceneMultimesh&&) noexcept = default;
SceneMultimesh& SceneMultimesh::operator=(SceneMultimesh&&) noexcept = default;

std::string cachedMeshPath(const std::string& scenePath) {
  const fs::path scene(scenePath);
  return (scene.parent_path() / scene.stem()).string() + ".ibmesh";
}

namespace {

// Passes progress on with the fraction never smaller than the last one passed on: a build that
// retries at a finer edge length meshes and maps again, and the bar then waits.
class MonotoneProgress {
 public:
  explicit MonotoneProgress(const PipelineProgress& out) : out_(out) {}
  void operator()(const std::string& stage, double fraction) {
    done_ = std::max(done_, std::clamp(fraction, 0.0, 1.0));
    if (out_) out_(stage, done_);
  }

 private:
  const PipelineProgress& out_;
  double done_ = 0;
};

// Share of the build (without Comesh) at the builder's stage: it reports each stage's own
// fraction, tracing every key in [0, 0.4), meshing the reference key at 0.4, mapping every key in
// [0.5, 1).
double buildFraction(const std::string& stage, double fraction) {
  if (stage.rfind("tracing", 0) == 0) return 0.4 * fraction;
  if (stage.rfind("meshing", 0) == 0) return 0.4;
  return 0.5 + 0.5 * fraction;
}

// Newer than the scene file, every drawing and the stiffness image.
bool cacheIsCurrent(const Scene& scene, const fs::path& cache) {
  std::error_code error;
  const auto cacheTime = fs::last_write_time(cache, error);
  if (error) return false;
  std::vector<std::string> inputs{scene.file};
  for (const KeySpec& key : scene.keys) inputs.push_back(key.drawing);
  if (!scene.stiffness.image.empty()) inputs.push_back(scene.stiffness.image);
  for (const std::string& input : inputs) {
    const auto inputTime = fs::last_write_time(input, error);
    if (error || inputTime > cacheTime) return false;
  }
  return true;
}

// A PNG's width and height from its header, or nothing when the file is not a readable PNG.
std::optional<std::array<int, 2>> pngSize(const std::string& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return std::nullopt;  // a pipe would block the read
  std::ifstream in(path, std::ios::binary);
  unsigned char head[24] = {};
  if (!in.read(reinterpret_cast<char*>(head), sizeof head)) return std::nullopt;
  static const unsigned char kSignature[12] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13};
  if (!std::equal(kSignature, kSignature + 12, head) || std::string(head + 12, head + 16) != "IHDR") return std::nullopt;
  const auto word = [&](int at) { return int(head[at]) << 24 | int(head[at + 1]) << 16 | int(head[at + 2]) << 8 | int(head[at + 3]); };
  return std::array<int, 2>{word(16), word(20)};
}

SceneMultimesh loaded(Multimesh mesh, MeshSource source, const std::string& file) {
  SceneMultimesh out;
  out.multimesh = std::make_shared<const Multimesh>(std::move(mesh));
  out.source = source;
  out.file = file;
  return out;
}

// Where Comesh Optimization crossed a line that matters, which the initial map had not: a key's
// smallest angle under kThinAngle degrees (a sliver that can crease the artwork drawn on it) or a
// map's MIPS maximum above kMipsLimit (a triangle sheared that far between two keys distorts the
// texture across it). Comesh minimizes a sum over every key and map, so it may trade one key's
// worst triangle for the rest; smaller trades (a smallest angle of 23 -> 14 degrees) are in
// `inbetween mesh`'s table, not worth a note. Empty when nothing crossed.
constexpr double kThinAngle = 10;   // degrees
constexpr double kMipsLimit = 20;

std::vector<std::string> comeshRegressions(const Scene& scene, const Multimesh& initial, const Multimesh& optimized) {
  const MultimeshQuality before = measureQuality(initial), after = measureQuality(optimized);
  const auto name = [&](int k) { return k < static_cast<int>(scene.keys.size()) ? inQuotes(scene.keys[k].name) : std::to_string(k); };
  std::vector<std::string> crossed;
  char text[200];
  for (size_t k = 0; k < before.keys.size() && k < after.keys.size(); ++k) {
    const KeyQuality &b = before.keys[k], &a = after.keys[k];
    if (a.smallestAngle < kThinAngle && b.smallestAngle >= kThinAngle) {
      std::snprintf(text, sizeof text, "key %s's smallest angle %.1f -> %.1f deg", name(static_cast<int>(k)).c_str(),
                    b.smallestAngle, a.smallestAngle);
      crossed.push_back(text);
    }
  }
  for (size_t i = 0; i < before.maps.size() && i < after.maps.size(); ++i) {
    const MapQuality &b = before.maps[i], &a = after.maps[i];
    if (a.from < a.to && a.mipsMax > kMipsLimit && b.mipsMax <= kMipsLimit) {  // each pair once: its MIPS is symmetric
      std::snprintf(text, sizeof text, "the MIPS maximum between %s and %s %.3g -> %.3g", name(a.from).c_str(), name(a.to).c_str(),
                    b.mipsMax, a.mipsMax);
      crossed.push_back(text);
    }
  }
  if (crossed.empty()) return {};
  std::string note = fs::path(scene.file).filename().string() + ": Comesh Optimization left ";
  for (size_t i = 0; i < crossed.size(); ++i) note += (i ? "; " : "") + crossed[i];
  note += " (under 10 deg, or above 20, where the initial map was not): a sliver or a strongly sheared triangle can crease "
          "the artwork there. If the frames show a crease, use the initial map (--no-comesh) or mesh finer (a smaller "
          "\"edge_length\"); `inbetween mesh` shows every figure and a picture of each key";
  return {note};
}

SceneMultimesh build(const Scene& scene, const SceneMultimeshOptions& options, MonotoneProgress& progress) {
  const double buildShare = options.comesh ? 0.3 : 1.0;  // of the whole call; Comesh takes the rest
  MultimeshBuildOptions buildOptions;
  buildOptions.traceCache = options.traceCache;
  buildOptions.previous = options.previous;
  buildOptions.progress = [&](const std::string& stage, double fraction) {
    progress(stage, buildShare * buildFraction(stage, fraction));
  };
  BuiltScene built = buildMultimesh(scene, buildOptions);
  SceneMultimesh out;
  out.source = MeshSource::kBuilt;
  out.shapes = std::move(built.shapes);
  out.drawingSizes = std::move(built.drawingSizes);
  out.edgeLength = built.edgeLength;
  out.initial = std::make_shared<const Multimesh>(std::move(*built.multimesh));
  out.multimesh = out.initial;
  if (!built.fallback.empty()) out.notes.push_back(fs::path(scene.file).filename().string() + ": " + built.fallback);
  if (!built.failedAttempts.empty()) out.notes.push_back(refinementNote(scene.file, built.edgeLength, built.failedAttempts));
  if (!options.comesh) return out;

  const ComeshOptions* given = options.comeshOptions;
  ComeshOptions comeshOptions = given ? *given : ComeshOptions{};
  comeshOptions.progress = [&](int outer, double energy) {
    if (given && given->progress) given->progress(outer, energy);
    char stage[96];
    std::snprintf(stage, sizeof stage, "comesh: outer iteration %d, energy %.6g", outer, energy);
    progress(stage, buildShare + (1 - buildShare) * outer / std::max(1, comeshOptions.outerIterations));
  };
  auto report = std::make_shared<ComeshReport>();
  Multimesh optimized = comeshOptimize(*out.initial, &built.boundary, comeshOptions, report.get());
  // Flips, splits and collapses made new triangles: paint them again from the scene.
  paintStiffness(optimized, scene.stiffness, scene.kappa);
  try {
    optimized.validate();
  } catch (const InputError& e) {  // the input was fine: a broken result is our fault (exit 1)
    throw std::runtime_error(std::string("Comesh Optimization produced an invalid multimesh: ") + e.what());
  }
  for (std::string& note : comeshRegressions(scene, *out.initial, optimized)) out.notes.push_back(std::move(note));
  out.multimesh = std::make_shared<const Multimesh>(std::move(optimized));
  out.comesh = std::move(report);
  return out;
}

}  // namespace

std::vector<std::string> sceneNotes(const Scene& scene) {
  std::vector<std::string> notes = scene.notes;
  std::vector<std::array<int, 2>> sizes;
  for (const KeySpec& key : scene.keys)
    if (const auto size = pngSize(key.drawing)) sizes.push_back(*size);
    else return notes;
  std::array<int, 2> largest{0, 0};
  std::string each;
  for (size_t k = 0; k < sizes.size(); ++k) {
    largest = {std::max(largest[0], sizes[k][0]), std::max(largest[1], sizes[k][1])};
    if (k < 6) each += (k ? ", " : "") + std::to_string(sizes[k][0]) + "x" + std::to_string(sizes[k][1]) + " for " + inQuotes(scene.keys[k].name);
  }
  if (sizes.size() > 6) each += ", ...";
  if (std::all_of(sizes.begin(), sizes.end(), [&](const std::array<int, 2>& s) { return s == sizes[0]; })) return notes;
  notes.push_back(fs::path(scene.file).filename().string() + ": keys have different canvas sizes (" + each +
                  "): positions are drawing pixels from each drawing's top-left, so the drawings line up at their "
                  "top-left corners; the renderer's canvas is the largest, " + std::to_string(largest[0]) + "x" +
                  std::to_string(largest[1]) + " (draw every key on the same canvas to place them otherwise)");
  return notes;
}

SceneMultimesh sceneMultimesh(const Scene& scene, const SceneMultimeshOptions& options, const PipelineProgress& progress) {
  MonotoneProgress report(progress);
  const int keys = static_cast<int>(scene.keys.size());
  if (!options.meshFile.empty()) {
    report("loading " + options.meshFile, 0);
    Multimesh mesh = loadMultimesh(options.meshFile);
    if (mesh.keyCount() != keys)
      throw InputError(options.meshFile + ": has " + std::to_string(mesh.keyCount()) + " keys but " + scene.file +
                       " has " + std::to_string(keys));
    report("multimesh loaded", 1);
    SceneMultimesh out = loaded(std::move(mesh), MeshSource::kFile, options.meshFile);
    out.notes = sceneNotes(scene);
    return out;
  }
  const std::string cache = cachedMeshPath(scene.file);
  if (options.useCache && cacheIsCurrent(scene, cache)) {
    try {
      report("loading " + cache, 0);
      Multimesh mesh = loadMultimesh(cache);
      if (mesh.keyCount() == keys) {
        report("multimesh loaded", 1);
        SceneMultimesh out = loaded(std::move(mesh), MeshSource::kCache, cache);
        out.notes = sceneNotes(scene);
        return out;
      }
    } catch (const InputError&) {  // a broken cache is rebuilt, not an error
    }
  }
  const ThreadLimit threads(options.threads);
  SceneMultimesh out = build(scene, options, report);
  std::vector<std::string> notes = sceneNotes(scene);
  notes.insert(notes.end(), out.notes.begin(), out.notes.end());  // Comesh's, after the scene's
  out.notes = std::move(notes);
  report("multimesh built", 1);
  return out;
}

std::vector<int> featureVertices(const Scene& scene, const Multimesh& mesh) {
  std::vector<int> out;
  for (int k = 0; k < static_cast<int>(scene.keys.size()) && k < mesh.keyCount(); ++k) {
    const Eigen::MatrixX2d X = mesh.keyPositions(k);
    for (const auto& [name, point] : scene.keys[k].features) {
      int best = -1;
      double bestDistance = std::numeric_limits<double>::infinity();
      for (int v : mesh.boundaryVertices(k)) {
        const double d = (X.row(v).transpose() - point).squaredNorm();
        if (d < bestDistance) {
          bestDistance = d;
          best = v;
        }
      }
      if (best >= 0) out.push_back(best);
    }
    for (const auto& [name, point] : scene.keys[k].interiorFeatures) {  // the build puts a vertex exactly there
      if (X.rows() == 0) break;
      Eigen::Index best = 0;
      (X.rowwise() - point.transpose()).rowwise().squaredNorm().minCoeff(&best);
      out.push_back(static_cast<int>(best));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string refinementNote(const std::string& sceneFile, double edgeLength, const std::vector<std::string>& failedAttempts) {
  char length[32];
  std::snprintf(length, sizeof length, "%.3g", edgeLength);
  std::string note = fs::path(sceneFile).filename().string() + ": built at edge length " + length +
                     " px, finer than asked: mapping the mesh onto every key without folding triangles failed ";
  for (size_t i = 0; i < failedAttempts.size(); ++i) note += (i ? "; then " : "") + failedAttempts[i];
  return note + " (each retry divides the edge length by 1.5). Set \"edge_length\" to " + length +
         " to skip the failed attempts, or check the features and cuts of that key there";
}

}  // namespace ib
