#include "bench/bench.h"

#include "core/error.h"
#include "core/suggest.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace ib {

void BenchOutput::printLine(nlohmann::json line) const {
  line["bench"] = bench_;
  line["arch"] = INBETWEEN_ARCH;
  std::printf("%s\n", line.dump().c_str());
  std::fflush(stdout);
}

StealMeter::StealMeter() : start_(read()) {}

std::optional<StealMeter::Ticks> StealMeter::read() {
  std::ifstream stat("/proc/stat");
  std::string label;
  long long fields[8] = {};  // user nice system idle iowait irq softirq steal
  if (!(stat >> label) || label != "cpu") return std::nullopt;
  for (long long& field : fields)
    if (!(stat >> field)) return std::nullopt;
  Ticks ticks;
  for (long long field : fields) ticks.total += field;
  ticks.steal = fields[7];
  return ticks;
}

void StealMeter::addTo(nlohmann::json& line) const {
  const std::optional<Ticks> now = read();
  if (!start_ || !now || now->total <= start_->total) return;
  line["steal_percent"] = 100.0 * double(now->steal - start_->steal) / double(now->total - start_->total);
}

std::filesystem::path bundledAssets(const std::string& bench) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  const fs::path assets = self.parent_path().parent_path() / "share" / "inbetween" / "assets";
  if (error || !fs::is_directory(assets, error))
    throw InputError("bench " + bench + ": no bundled scenes at " + assets.string() +
                     ": give --assets DIR, a folder of NAME/scene.json (the source tree's assets/)");
  return assets;
}

std::vector<std::filesystem::path> benchScenes(const std::filesystem::path& assets, const std::vector<std::string>& only,
                                               const std::string& bench) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(assets)) throw InputError("bench " + bench + ": --assets: " + assets.string() + " is not a folder");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(assets))
    if (fs::exists(entry.path() / "scene.json")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  if (names.empty())
    throw InputError("bench " + bench + ": --assets: no NAME/scene.json in " + assets.string() +
                     ": give a folder of scene folders (the source tree's assets/)");
  for (const std::string& name : only)
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string all;
      for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
      throw InputError("bench " + bench + ": --scenes: " + inQuotes(name) + " is not a scene of " + assets.string() +
                       didYouMean(name, names) + "; the scenes there: " + all);
    }
  std::vector<fs::path> scenes;
  for (const std::string& name : names)
    if (only.empty() || std::find(only.begin(), only.end(), name) != only.end()) scenes.push_back(assets / name / "scene.json");
  return scenes;
}

double edgeLengthOption(const cli::Arguments& arguments) {
  if (!arguments.has("edge-length")) return 0;
  const std::string text = arguments.value("edge-length", "");
  char* end = nullptr;
  const double edgeLength = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(edgeLength >= 0.5 && edgeLength <= 1000))
    throw InputError("--edge-length: '" + text + "' is not a length in [0.5, 1000] px");
  return edgeLength;
}

std::filesystem::path sceneWithEdgeLength(const std::filesystem::path& file, double edgeLength, const std::string& bench) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("inbetween-bench-" + bench + "-" + file.parent_path().filename().string());
  fs::remove_all(dir);
  fs::copy(file.parent_path(), dir, fs::copy_options::recursive);
  std::ifstream in(file);
  nlohmann::json scene = nlohmann::json::parse(in);
  if (edgeLength > 0) scene["edge_length"] = edgeLength;
  std::ofstream(dir / "scene.json") << scene.dump(2);
  return dir / "scene.json";
}

SceneMultimesh builtFromDrawings(const Scene& scene, int threads, const std::string& name, cli::Progress& progress, double share) {
  SceneMultimeshOptions options;
  options.useCache = false;
  options.threads = threads;
  return sceneMultimesh(scene, options, [&](const std::string& stage, double f) { progress.update(name + ": " + stage, share * f); });
}

void showStatus(const std::string& text) {
  if (isatty(STDERR_FILENO)) std::fprintf(stderr, "\r\033[K%s", text.c_str());
}

namespace {

std::vector<Benchmark> benchmarks() {
  return {interpBenchmark(), comeshBenchmark(), animBenchmark(), meshBenchmark(),
#ifdef INBETWEEN_WITH_ENGINE
          renderBenchmark(), playBenchmark(), editBenchmark(), ghostBenchmark(), keysBenchmark(),
#endif
          cutBenchmark(), popsBenchmark(), shapeBenchmark(), examplesBenchmark()};
}

std::string usage(const std::vector<Benchmark>& all) {
  std::string out =
      "usage: inbetween bench CASE [OPTIONS]\n"
      "\n"
      "Benchmarks; each prints one JSON object per case on its own line, with \"bench\" (the CASE)\n"
      "and \"arch\" (the instruction set this inbetween was built for).\n"
      "\n"
      "cases:\n";
  size_t width = 0;  // the longest name, then two spaces before every summary
  for (const Benchmark& b : all) width = std::max(width, std::string(b.name).size());
  for (const Benchmark& b : all) out += "  " + std::string(b.name) + std::string(width + 2 - std::string(b.name).size(), ' ') + b.summary + "\n";
  return out + "\nSee `inbetween bench CASE --help` for a case's options and fields.\n";
}

}  // namespace

int runBench(const std::vector<std::string>& args) {
  const std::vector<Benchmark> all = benchmarks();
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::fputs(usage(all).c_str(), args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  for (const Benchmark& b : all) {
    if (args[0] != b.name) continue;
    if (cli::printHelpIfAsked(rest, b.usage)) return 0;
    const std::string command = "bench " + args[0];
    const cli::Arguments arguments(command, rest, b.valueOptions, b.flagOptions);
    if (!arguments.positional().empty())
      throw InputError(command + ": unexpected argument '" + arguments.positional()[0] + "'");
    b.run(arguments, BenchOutput(b.name));
    return 0;
  }
#ifndef INBETWEEN_WITH_ENGINE
  if (args[0] == "render" || args[0] == "play" || args[0] == "edit")
    throw InputError("bench " + args[0] + ": this inbetween was built without the engine (INBETWEEN_ENGINE=OFF)");
#endif
  std::string names;
  for (const Benchmark& b : all) names += (names.empty() ? "" : ", ") + std::string(b.name);
  throw InputError("bench: unknown case '" + args[0] + "' (available: " + names + ")");
}

}  // namespace ib
