// `inbetween bench edit`: the editor's window on every bundled scene (a copy, so nothing is
// saved over it): the time from moving one feature to the first frame drawn with the multimesh
// that edit started (the initial map, rebuilt in the background), and the window's frame times
// while rebuilds run (the quick one and the Comesh-optimized one after it). Needs a display (Xvfb
// will do); one JSON line per scene.
#include "bench/bench.h"

#include "commands/render_options.h"
#include "core/error.h"
#include "editor/editor_session.h"
#include "editor/editor_view.h"
#include "gpu/glfw_window.h"
#include "gpu/vulkan_check.h"
#include "multimesh/multimesh.h"
#include "player/player_window.h"
#include "progress.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween bench edit [--assets DIR] [--scenes LIST] [--edits N] [--size WxH] [--edge-length PX]\n"
    "\n"
    "Opens the editor's window (`inbetween edit`) on a copy of every scene DIR/NAME/scene.json with its\n"
    "animation playing, and N times moves the reference key's first feature 3 px along its outline (back\n"
    "and forth), as a drag does (without features, its first cut's first point 1 px; a scene with neither\n"
    "gets a feature at the top of every key first). Each edit is timed until the first presented frame solved on the\n"
    "multimesh it started; then frames are presented until the optimized rebuild that follows is in\n"
    "(at most 120 s), and half a second more. Needs a display: run under\n"
    "`xvfb-run -a -s \"-screen 0 1920x1080x24\"`.\n"
    "One JSON line per scene: scene, vertices (of the multimesh the edit built), keys, edits,\n"
    "latency_ms (median), latency_max_ms, rebuild_frames (frames presented while a rebuild ran),\n"
    "rebuild_p50_ms, rebuild_p95_ms (their frame times), optimized_s (the optimized rebuild, median),\n"
    "idle_p50_ms, idle_p95_ms (frame times playing without a rebuild, before the edits);\n"
    "edit (what was timed: a feature moved, or without one a cut's point moved 1 px across it and back);\n"
    "a scene with cuts but no feature in its reference key reports \"skipped\".\n"
    "\n"
    "  --assets DIR      folder of scenes (default: the bundled scenes)\n"
    "  --scenes LIST     comma-separated scene folder names (default: every one)\n"
    "  --edits N         feature moves timed (default 5)\n"
    "  --size WxH        window size (default 1280x720)\n"
    "  --edge-length PX  mesh every scene at this boundary edge length instead of its own (larger meshes)\n";

using Clock = std::chrono::steady_clock;

constexpr double kSettleSeconds = 0.5;  // s of frames presented after an optimized rebuild, before the next edit

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<size_t>(p * static_cast<double>(values.size())))];
}

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The edit timed on a scene: the reference key's first feature moved 3 px along its outline and
// back, as a drag leaves it; without features, its first cut's first point moved 1 px across the
// cut and back. A scene with neither gets a feature at the top of every key's outline first (not
// timed); one with cuts but no features elsewhere is skipped (such a feature would have to fit
// in with the cuts' own).
struct TimedEdit {
  std::string what;                              // e.g. "move feature `f1`"
  std::function<edit::SceneEdit(int e)> next;    // the e-th edit, from 0
};

std::optional<TimedEdit> timedEdit(editor::EditorSession& editing, editor::EditorView& view, int reference) {
  const editor::KeyMarks& key = editing.marks().keys[static_cast<size_t>(reference)];
  const std::string keyName = key.name;
  std::string feature = key.features.empty() ? std::string() : key.features.begin()->first;
  if (feature.empty() && !key.cuts.empty() && key.cuts.front().points.size() >= 2) {
    const editor::CutMark cut = key.cuts.front();
    const Eigen::Vector2d p = cut.points[0], along = (cut.points[1] - p).normalized();
    const Eigen::Vector2d across(-along.y(), along.x());
    return TimedEdit{"move point 0 of cut `" + cut.name + "`", [keyName, cut, p, across](int e) -> edit::SceneEdit {
                       return edit::MoveCutPoint{keyName, cut.name, 0, e % 2 == 0 ? Eigen::Vector2d(p + across) : p};
                     }};
  }
  if (feature.empty()) {
    for (const editor::KeyMarks& k : editing.marks().keys)
      if (!k.cuts.empty()) return std::nullopt;
    feature = "bench";
    for (int k = 0; k < editing.keyCount(); ++k) {
      const RgbaImage& d = view.drawings()[static_cast<size_t>(k)];
      const std::optional<Eigen::Vector2d> top =
          editing.snap(k, Eigen::Vector2d(d.width / 2.0, 0), static_cast<double>(d.width + d.height));
      if (!top) throw std::runtime_error("bench edit: key " + editing.marks().keys[static_cast<size_t>(k)].name + " has no outline");
      editing.apply(edit::SetFeature{editing.marks().keys[static_cast<size_t>(k)].name, feature, *top});
    }
  }
  return TimedEdit{"move feature `" + feature + "`", [&editing, reference, keyName, feature](int e) -> edit::SceneEdit {
                     // The next point 3 px along the outline (alternating directions), as a drag leaves it.
                     const Eigen::Vector2d at = editing.marks().keys[static_cast<size_t>(reference)].features.at(feature);
                     const double dx = e % 2 == 0 ? 3 : -3;
                     std::optional<Eigen::Vector2d> to = editing.snap(reference, at + Eigen::Vector2d(dx, 0), 6);
                     if (!to || (*to - at).norm() < 0.5) to = editing.snap(reference, at + Eigen::Vector2d(0, dx), 6);
                     if (!to) throw std::runtime_error("bench edit: no outline point near feature " + feature);
                     return edit::SetFeature{keyName, feature, *to};
                   }};
}

nlohmann::json benchScene(const std::filesystem::path& file, const play::PlayerWindowOptions& base, int edits) {
  const std::string name = file.parent_path().filename().string();
  cli::Progress progress;
  editor::EditorSession editing(SceneDocument::load(file.string()));
  auto reloader = std::make_unique<play::SceneReloader>(file.string(), [&](const std::string& stage, double f) {
    progress.update(name + ": " + stage, f);
  });
  progress.finish();
  play::PlayerSession session(std::move(reloader), {});
  play::PlayerWindowOptions options = base;
  options.editor = &editing;
  play::PlayerWindow window(session, options);
  editor::EditorView& view = *window.editor();
  const int reference = std::max(0, editing.marks().keyIndex(editing.marks().reference));
  const std::optional<TimedEdit> timed = timedEdit(editing, view, reference);
  if (!timed) return {{"scene", name}, {"skipped", "no feature to move, and cuts where one could be added"}};
  session.transport().play();
  for (int f = 0; f < 30; ++f) window.frame();
  // Frame times without a rebuild, for comparison, playing.
  std::vector<double> idleMs;
  for (Clock::time_point last = Clock::now(); idleMs.size() < 120;) {
    window.frame();
    const Clock::time_point now = Clock::now();
    idleMs.push_back(1000 * std::chrono::duration<double>(now - last).count());
    last = now;
  }

  std::vector<double> latencies, frameMs, optimized;
  for (int e = 0; e < edits; ++e) {
    const int generation = editing.generation();
    const Clock::time_point start = Clock::now();
    view.apply(timed->next(e));
    if (editing.generation() == generation)
      throw std::runtime_error("bench edit: " + name + ": " + timed->what + " was refused: " + view.status());
    Clock::time_point last = Clock::now();
    bool sent = false;
    for (;;) {
      window.frame();
      const Clock::time_point now = Clock::now();
      if (session.reloader().busy()) frameMs.push_back(1000 * std::chrono::duration<double>(now - last).count());
      last = now;
      sent = sent || view.awaitingFrame();
      if (sent && !view.awaitingFrame()) break;
      if (since(start) > 120) {
        std::string why = editing.document().problem() ? *editing.document().problem() : std::string();
        for (const auto& m : session.messages())
          if (m.error) why = m.text;
        throw std::runtime_error("bench edit: " + name + ": no frame of the edit within 120 s" + (why.empty() ? "" : ": " + why));
      }
    }
    latencies.push_back(1000 * since(start));
    // The optimized rebuild that follows once the edits pause, drawn through.
    const Clock::time_point quiet = Clock::now();
    bool started = false;
    while (since(quiet) < 120) {
      window.frame();
      const Clock::time_point now = Clock::now();
      const bool busy = session.reloader().busy();
      if (busy) frameMs.push_back(1000 * std::chrono::duration<double>(now - last).count());
      last = now;
      started = started || busy;
      if (started && !busy) break;
    }
    if (started) optimized.push_back(since(quiet));
    // The optimized multimesh swapped in and drawn before the next edit, as after a user's pause.
    for (const Clock::time_point settle = Clock::now(); since(settle) < kSettleSeconds;) window.frame();
    last = Clock::now();
  }
  return {{"scene", name},
          {"vertices", session.renderMesh().vertexCount},
          {"keys", editing.keyCount()},
          {"edits", edits},
          {"edit", timed->what},
          {"latency_ms", percentile(latencies, 0.5)},
          {"latency_max_ms", *std::max_element(latencies.begin(), latencies.end())},
          {"rebuild_frames", frameMs.size()},
          {"rebuild_p50_ms", percentile(frameMs, 0.5)},
          {"rebuild_p95_ms", percentile(frameMs, 0.95)},
          {"optimized_s", percentile(optimized, 0.5)},
          {"idle_p50_ms", percentile(idleMs, 0.5)},
          {"idle_p95_ms", percentile(idleMs, 0.95)},
          {"device", window.context().deviceName()}};
}

void run(const cli::Arguments& a, const BenchOutput& output) {
  const std::filesystem::path assets = a.has("assets") ? std::filesystem::path(a.value("assets", "")) : bundledAssets("edit");
  const std::vector<std::string> only = a.has("scenes") ? cli::wordList(a.value("scenes", ""), "--scenes") : std::vector<std::string>{};
  const std::vector<std::filesystem::path> files = benchScenes(assets, only, "edit");
  play::PlayerWindowOptions options;
  const std::array<int, 2> size = parseSize(a.value("size", "1280x720"), "--size");
  options.width = size[0];
  options.height = size[1];
  options.vsync = false;
  options.device = vk::DevicePreference::kSoftware;
  const int edits = a.integer("edits", 5, 1, 1000);
  const double edgeLength = edgeLengthOption(a);
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY"))
    throw InputError("bench edit: no display (DISPLAY is not set); run it under xvfb-run -a");
  for (const auto& file : files) {
    try {
      nlohmann::json line = benchScene(sceneWithEdgeLength(file, edgeLength, "edit"), options, edits);
      line["scene"] = file.parent_path().filename().string();
      if (edgeLength > 0) line["edge_length"] = edgeLength;
      output.printLine(line);
    } catch (const vk::WindowError& e) {
      throw InputError(std::string("bench edit: ") + e.what());
    } catch (const vk::VulkanError& e) {
      throw InputError(std::string("bench edit: no usable Vulkan device: ") + e.what());
    }
  }
}

}  // namespace

Benchmark editBenchmark() {
  return {"edit", "the editor's window: from a feature moved to the frame drawn with it", kUsage,
          {"assets", "scenes", "edits", "size", "edge-length"}, {}, run};
}

}  // namespace ib
