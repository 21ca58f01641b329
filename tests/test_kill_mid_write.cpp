// Outputs are replaced atomically: every command that writes files (mesh, render, export as .glb
// and as .gltf + .bin, play's screenshot, play's saved scene) is killed with SIGKILL at each of its write, fsync and
// rename system calls in turn (strace's fault injection), over the outputs of an earlier run.
// After every kill each output is byte for byte either the earlier file or the complete new one,
// never a mix, a truncation or nothing.
#include "core/error.h"
#include "core/png_image.h"
#include "testkit/command_run.h"

#include <catch2/catch.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>

namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(INBETWEEN_ASSETS) + "/square-arch-notch/scene.json";

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Every regular file under dir (relative name -> bytes), leftover temporary files excluded.
std::map<std::string, std::string> filesUnder(const fs::path& dir) {
  std::map<std::string, std::string> files;
  if (!fs::exists(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().filename().string().find(".tmp-") == std::string::npos)
      files[fs::relative(entry.path(), dir).string()] = slurp(entry.path());
  return files;
}

struct Writer {
  std::string name;
  std::string older, newer;  // the command's arguments (OUT: the output folder) for the two versions
  // The player's screenshot shows its UI (frame times among it), so no two runs give the same
  // bytes: a new screenshot is recognized as a whole PNG of the new size instead.
  std::array<int, 2> newPicture{0, 0};
  bool sceneInOut = false;  // the command edits a scene: a copy of kScene's folder starts in OUT
};

bool wholePicture(const std::string& bytes, std::array<int, 2> size) {
  try {
    const ib::RgbaImage image = ib::decodePng(bytes, "screenshot");
    return image.width == size[0] && image.height == size[1];
  } catch (const ib::InputError&) {
    return false;
  }
}

// The next call to kill at: every one in the normal build; under the sanitizers, where each run takes
// seconds, the first four and then every 1.5x (the later writes of a file go through the same code).
int nextKill(int when) {
#ifdef INBETWEEN_SANITIZED
  return when < 4 ? when + 1 : when + when / 2;
#else
  return when + 1;
#endif
}

}  // namespace

TEST_CASE("atomic writes: a command killed at any write, fsync or rename leaves each output the earlier file or the new one, whole", "[.kill]") {
  const std::vector<Writer> writers = {
      {"mesh", "mesh " + kScene + " -o OUT/out.ibmesh --no-pictures --no-comesh",
       "mesh " + std::string(INBETWEEN_ASSETS) + "/pentagon-star/scene.json -o OUT/out.ibmesh --no-pictures --no-comesh"},
      {"render", "render " + kScene + " -o OUT --frames 0:1 --size 48x48 --no-comesh --device cpu",
       "render " + kScene + " -o OUT --frames 0:1 --size 64x48 --no-comesh --device cpu"},
      {"export glb", "export " + kScene + " -o OUT/out.glb --no-comesh", "export " + kScene + " -o OUT/out.glb --no-comesh --quantize"},
      {"export gltf", "export " + kScene + " -o OUT/out.gltf --no-comesh", "export " + kScene + " -o OUT/out.gltf --no-comesh --quantize"},
      {"play screenshot", "play " + kScene + " --frames 1 --screenshot OUT/shot.png --size 64x64 --device cpu",
       "play " + kScene + " --frames 1 --screenshot OUT/shot.png --size 80x64 --device cpu", {80, 64}},
      {"play save", "play OUT/scene.json --frames 1 --size 64x64 --device cpu --set tau=0.002 --save",
       "play OUT/scene.json --frames 1 --size 64x64 --device cpu --set tau=0.004 --save", {0, 0}, true},
  };
  const fs::path root = fs::path(INBETWEEN_BUILD) / "kill-mid-write";
  for (const Writer& writer : writers) {
    INFO(writer.name);
    const fs::path out = root / std::regex_replace(writer.name, std::regex(" "), "-");
    const auto run = [&](const std::string& arguments, const std::string& strace) {
      return test::runCommand(strace + std::string(INBETWEEN_CLI) + " " + std::regex_replace(arguments, std::regex("OUT"), out.string()));
    };
    const auto fresh = [&] {
      fs::remove_all(out);
      fs::create_directories(out);
      if (writer.sceneInOut)
        for (const auto& entry : fs::directory_iterator(fs::path(kScene).parent_path()))
          if (entry.path().extension() == ".json" || entry.path().extension() == ".png") fs::copy_file(entry.path(), out / entry.path().filename());
    };
    // The new version, once, for reference; then the earlier one, which every killed run starts from.
    fresh();
    REQUIRE(run(writer.newer, "").code == 0);
    const std::map<std::string, std::string> newer = filesUnder(out);
    fresh();
    REQUIRE(run(writer.older, "").code == 0);
    const std::map<std::string, std::string> older = filesUnder(out);
    REQUIRE(older.size() == newer.size());
    int kills = 0;
    for (const std::string call : {"rename", "fsync", "write"}) {
      for (int when = 1; when <= 200; when = nextKill(when)) {
        // Back to the earlier outputs (killed runs may have replaced some), leftovers removed.
        fs::remove_all(out);
        fs::create_directories(out);
        for (const auto& [name, bytes] : older) {
          fs::create_directories((out / name).parent_path());
          std::ofstream(out / name, std::ios::binary) << bytes;
        }
        const test::CommandRun killed = run(writer.newer, "strace -f -qq -o /dev/null -e trace=" + call + " -e inject=" + call +
                                                              ":signal=KILL:when=" + std::to_string(when) + " ");
        const std::map<std::string, std::string> now = filesUnder(out);
        INFO("killed at " << call << " " << when << ", exit " << killed.code);
        CHECK(now.size() == older.size());
        for (const auto& [name, bytes] : now) {
          INFO(name);
          const bool isNewer = writer.newPicture[0] ? wholePicture(bytes, writer.newPicture) : newer.count(name) && bytes == newer.at(name);
          CHECK((bytes == older.at(name) || isNewer));
        }
        if (killed.code == 0) break;  // ran to the end: every call of this kind was tried
        ++kills;
      }
    }
    CHECK(kills >= 3);
  }
}
