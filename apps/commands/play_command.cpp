#include "commands/play_command.h"

#include "cli.h"
#include "commands/render_options.h"
#include "commands/scene_overrides.h"
#include "core/error.h"
#include "editor/editor_session.h"
#include "editor/editor_view.h"
#include "gpu/vulkan_check.h"
#include "player/player_window.h"
#include "progress.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween play SCENE [--frames N [--screenshot PATH] [--save]] [--set NAME=VALUE]... [--weights K=W,...]\n"
    "                            [--size WxH] [--device D] [--validation]\n"
    "\n"
    "Plays the scene in a window (Vulkan; lavapipe without a GPU) with every parameter as a slider:\n"
    "transport, weights mode, parameters, view, readouts, files; the Help tab lists the keys.\n"
    "The multimesh comes from the cache beside the scene when current, else it is built now. Edits to\n"
    "the scene or its drawings are picked up while it plays; drop a scene.json on the window to open it.\n"
    "\n"
    "  --frames N          scripted: present N frames and exit. Timeline frames 0..N-1 (wrapping), each\n"
    "                      solved before it is drawn, so the picture is the same on every run\n"
    "  --screenshot PATH   scripted: write the last frame's window, UI included, as PNG\n"
    "  --save              scripted: then write the parameters into the scene, as Save parameters does\n"
    "  --set NAME=VALUE    a control's starting value (repeatable): any live parameter of `inbetween\n"
    "                      parameters` (the solver's, the dynamics', kappa_scale, dynamics), e.g. tau=1e-9\n"
    "  --weights K=W,...   weights mode at these weights (K a key's name or index; others 0; normalized)\n"
    "  --size WxH          window size in pixels (default 1280x720)\n"
    "  --samples N         multisample anti-aliasing samples (default 2)\n"
    "  --sampling S        the drawings' filtering at the start: linear or nearest (pixel art);\n"
    "                      default the scene's \"sampling\" (auto: nearest for pixel art)\n"
    "  --no-vsync          present as fast as possible (mailbox or immediate)\n"
    "  --device D          any (default: a GPU if present, else lavapipe), gpu or cpu\n"
    "  --validation        run with the Khronos validation layer; any message is an error\n"
    "  --threads N         the most solver threads, 0 = all cores (default); fewer run while the window's\n"
    "                      drawing or other programs keep cores busy\n";

// "K=W,..." over the scene's keys: K a name or an index.
Eigen::VectorXd parseWeights(const std::string& text, const std::vector<std::string>& keys) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(keys.size()));
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos) throw InputError("--weights: '" + item + "' is not KEY=WEIGHT");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    int index = -1;
    for (size_t k = 0; k < keys.size(); ++k)
      if (keys[k] == key) index = static_cast<int>(k);
    if (index < 0 && !key.empty() && key.find_first_not_of("0123456789") == std::string::npos && key.size() < 6)
      index = std::atoi(key.c_str());
    if (index < 0 || index >= static_cast<int>(keys.size())) {
      std::string names;
      for (const std::string& k : keys) names += (names.empty() ? "" : ", ") + k;
      throw InputError("--weights: '" + key + "' is not a key (keys: " + names + ", or 0.." + std::to_string(keys.size() - 1) + ")");
    }
    char* end = nullptr;
    const double weight = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(weight) || weight < 0)
      throw InputError("--weights: '" + value + "' for key " + key + " is not a weight >= 0");
    w[index] = weight;
  }
  if (w.sum() <= 0) throw InputError("--weights: '" + text + "' gives no key a positive weight");
  return w / w.sum();
}

// Opens the window; a missing display or Vulkan device is the machine's problem (exit 2).
std::unique_ptr<play::PlayerWindow> openWindow(play::PlayerSession& session, const play::PlayerWindowOptions& options) {
  try {
    return std::make_unique<play::PlayerWindow>(session, options);
  } catch (const vk::WindowError& e) {
    throw InputError(std::string("play: ") + e.what());
  } catch (const vk::VulkanError& e) {
    throw InputError(std::string("play: no usable Vulkan device: ") + e.what() +
                     " (lavapipe comes with Debian's mesa-vulkan-drivers; see scripts/setup.sh)");
  }
}

void requireSilentValidation(const play::PlayerWindow& window, bool validation) {
  if (validation && !window.context().validationMessages().empty())
    throw std::runtime_error("play: the validation layer reported: " + window.context().validationMessages().front());
}

// The scripted run: `frames` frames, each solved before it is presented; the last one captured.
void runScripted(play::PlayerSession& session, play::PlayerWindow& window, int frames, const std::string& screenshot) {
  constexpr double kSolveTimeout = 600;  // s: a frame of a large scene on a slow machine
  RgbaImage shot;
  for (int i = 0; i < frames; ++i) {
    if (!session.weightsMode()) session.transport().goTo(i % session.transport().frameCount());
    session.update(0);  // sends the parameters and asks for the frame
    if (!session.worker().waitIdle(kSolveTimeout))
      throw std::runtime_error("play: frame " + std::to_string(i) + " was not solved within " + std::to_string(int(kSolveTimeout)) + " s");
    const bool last = i + 1 == frames;
    bool presented = window.frame(last && !screenshot.empty() ? &shot : nullptr);
    for (int retry = 0; last && !presented && retry < 10; ++retry)  // a rebuilt swapchain skips a frame
      presented = window.frame(screenshot.empty() ? nullptr : &shot);
    if (last && !presented) throw std::runtime_error("play: the window presented no frame to capture");
  }
  if (!screenshot.empty()) writePng(screenshot, shot);
}

}  // namespace

int runPlay(const std::vector<std::string>& rawArgs) {
  if (cli::printHelpIfAsked(rawArgs, kUsage)) return 0;
  return runPlayerWindow(rawArgs, false);
}

int runPlayerWindow(const std::vector<std::string>& rawArgs, bool edit) {
  const char* const command = edit ? "edit" : "play";
  const cli::SplitSets split = cli::takeSets(rawArgs, command);
  const cli::Arguments arguments(command, split.rest, {"frames", "screenshot", "weights", "size", "samples", "sampling", "device", "threads"},
                                 {"validation", "no-vsync", "save"});
  if (arguments.positional().size() != 1)
    throw InputError(std::string(command) + ": needs exactly one SCENE file (see `inbetween " + command + " --help`)");
  const std::string scenePath = arguments.positional()[0];
  // The editor's document: read first, so a scene that does not load is the usual message.
  std::unique_ptr<editor::EditorSession> editing;
  if (edit) {
    SceneDocument document = SceneDocument::load(scenePath);
    if (document.problem()) throw InputError(*document.problem());
    editing = std::make_unique<editor::EditorSession>(std::move(document));
  }
  const int frames = arguments.integer("frames", 0, 1, 1000000);
  const std::string screenshot = arguments.value("screenshot", "");
  if (!screenshot.empty() && !arguments.has("frames")) throw InputError("play: --screenshot needs --frames N (a scripted run)");
  const bool save = arguments.flag("save");
  if (save && !arguments.has("frames")) throw InputError("play: --save needs --frames N (a scripted run; in the window, Save parameters)");
  play::PlayerWindowOptions windowOptions;
  if (arguments.has("size")) {
    const std::array<int, 2> size = parseSize(arguments.value("size", ""), "--size");
    windowOptions.width = size[0];
    windowOptions.height = size[1];
  }
  windowOptions.samples = arguments.integer("samples", windowOptions.samples, 1, 64);
  windowOptions.vsync = !arguments.flag("no-vsync");
  windowOptions.sampling = parseSampling(arguments);
  windowOptions.validation = arguments.flag("validation");
  const std::string device = arguments.value("device", "any");
  if (device == "any") windowOptions.device = vk::DevicePreference::kAny;
  else if (device == "gpu") windowOptions.device = vk::DevicePreference::kHardware;
  else if (device == "cpu") windowOptions.device = vk::DevicePreference::kSoftware;
  else throw InputError("--device: '" + device + "' is not any, gpu or cpu");
  play::SolveWorker::Options workerOptions;
  workerOptions.threads = arguments.integer("threads", 0, 0, cli::kMaxThreads);
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY"))  // before the long work: fail fast
    throw InputError("play: cannot open a window: no display (neither DISPLAY nor WAYLAND_DISPLAY is set); "
                     "`inbetween render` draws frames headless");

  // The initial load reports on the terminal; later rebuilds run on the reloader's thread and
  // show their progress in the window instead.
  cli::Progress progress;
  const auto loading = std::make_shared<std::atomic<bool>>(true);
  auto reloader = std::make_unique<play::SceneReloader>(scenePath, [&progress, loading](const std::string& stage, double f) {
    if (*loading) progress.update(stage, f);
  });
  *loading = false;
  progress.finish();
  play::PlayerSession session(std::move(reloader), workerOptions);
  for (const std::string& note : sceneNotes(session.scene().scene)) {  // on stderr, and in the window's messages
    std::fprintf(stderr, "inbetween: note: %s\n", note.c_str());
    session.messages().push_back({"note: " + note, false});
  }
  for (const std::string& assignment : split.sets) session.parameters().setFromText(assignment);
  if (arguments.has("weights")) {
    session.setWeights(parseWeights(arguments.value("weights", ""), session.keyNames()));
    session.setWeightsMode(true);
  }
  windowOptions.editor = editing.get();
  const std::unique_ptr<play::PlayerWindow> window = openWindow(session, windowOptions);
  if (frames > 0) {
    runScripted(session, *window, frames, screenshot);
    requireSilentValidation(*window, windowOptions.validation);
    if (!screenshot.empty()) std::printf("%s: %d frames presented; wrote %s\n", scenePath.c_str(), frames, screenshot.c_str());
    if (save) {  // what the Save parameters button does, with its error as this command's
      session.writeParameters();  // in edit mode into the document, then the file
      std::printf("%s: saved the parameters\n", scenePath.c_str());
    }
    return 0;
  }
  window->run();
  requireSilentValidation(*window, windowOptions.validation);
  return 0;
}

}  // namespace ib
