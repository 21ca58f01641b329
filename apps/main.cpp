// The `inbetween` command: a thin front end over the solver and the engine.
// Exit codes: 0 success, 2 bad input (message names the file, field or option), 1 internal error.
#include "commands/bench_launcher.h"
#include "commands/edit_command.h"
#include "commands/export_command.h"
#include "commands/mesh_command.h"
#include "commands/parameters_command.h"
#ifdef INBETWEEN_WITH_ENGINE
#include "commands/play_command.h"
#include "commands/render_command.h"
#endif
#include "core/error.h"
#include "core/suggest.h"

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

// The engine's commands are listed only when this build has them (INBETWEEN_ENGINE).
#ifdef INBETWEEN_WITH_ENGINE
#define ENGINE_COMMAND(line) line
#else
#define ENGINE_COMMAND(line) ""
#endif

constexpr const char* kUsage =
    "usage: inbetween COMMAND [OPTIONS]\n"
    "\n"
    "Interpolates key drawings (Zhu, Popovic, Bridson, Kaufman 2017).\n"
    "\n"
    "commands:\n"
    "  mesh SCENE     build and optimize the multimesh of a scene (see `inbetween mesh --help`)\n"
    "  export SCENE   export the scene's animation as glTF 2.0 (.glb / .gltf) (see `inbetween export --help`)\n"
    ENGINE_COMMAND("  render SCENE   render the scene's animation to PNG frames, headless (see `inbetween render --help`)\n")
    ENGINE_COMMAND("  play SCENE     play the scene in a window with every parameter as a slider (see `inbetween play --help`)\n")
    "  new SCENE A.png B.png ...   start a scene from drawings, one key each (see `inbetween new --help`)\n"
    "  edit SCENE --apply OPS.json   apply operations to a scene: keys, features, cuts, marks (see `inbetween edit --help`)\n"
    "  parameters     every parameter a scene, --set and the player take (see `inbetween parameters --help`)\n"
    "  bench interp   benchmark the interpolation solver; one JSON object per case\n"
    "  bench comesh   benchmark Comesh Optimization; one JSON object per case\n"
    "  bench anim     benchmark playing every bundled scene's timeline; one JSON object per case\n"
    "  bench mesh     benchmark building every bundled scene's multimesh; one JSON object per scene\n"
    ENGINE_COMMAND("  bench render   benchmark headless rendering (frames per second); one JSON object per case\n")
    ENGINE_COMMAND("  bench play     benchmark the player's window (fps, frame times, parameter latency); needs a display\n")
    "  bench cut      benchmark the solver through a cut letting go; one JSON object per case\n"
    "  bench shape    how full-bodied and evenly paced the inbetweens are; one JSON object per scene and metric\n"
    "  bench examples the paper's examples, as its Tables 2 and 3\n"
    "\n"
    "options:\n"
    "  -h, --help     show this help (also: inbetween COMMAND --help)\n"
    "  --version      show the version\n";

int run(const std::vector<std::string>& args) {
  if (args.empty()) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string& command = args[0];
  if (command == "-h" || command == "--help" || command == "help") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (command == "--version" || command == "version") {
    std::printf("inbetween %s (built for %s)\n", INBETWEEN_VERSION, INBETWEEN_ARCH);
    return 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "bench") ib::runBenchProgram(rest);
  if (command == "mesh") return ib::runMesh(rest);
  if (command == "parameters") return ib::runParameters(rest);
  if (command == "edit") return ib::runEdit(rest);
  if (command == "new") return ib::runNew(rest);
  if (command == "export") return ib::runExport(rest);
#ifdef INBETWEEN_WITH_ENGINE
  if (command == "render") return ib::runRender(rest);
  if (command == "play") return ib::runPlay(rest);
#else
  if (command == "render" || command == "play")
    throw ib::InputError(command + ": this inbetween was built without the engine (INBETWEEN_ENGINE=OFF)");
#endif
  throw ib::InputError("unknown command '" + command + "'" +
                       ib::didYouMean(command, {"mesh", "render", "play", "export", "parameters", "new", "edit", "bench"}) +
                       " (see `inbetween --help`)");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const ib::InputError& e) {
    std::fprintf(stderr, "inbetween: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inbetween: internal error: %s\n", e.what());
    return 1;
  } catch (...) {
    std::fprintf(stderr, "inbetween: internal error\n");
    return 1;
  }
}
