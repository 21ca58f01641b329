#include "cli_support.h"

#include "testkit/drawings.h"
#include "testkit/example_scenes.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace test {

namespace fs = std::filesystem;

namespace {

// This process's scratch folder, made on first use and removed at exit.
class Scratch {
 public:
  Scratch() : folder_(scratchDirectory("cli")) {}
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(folder_, ignored);
  }
  const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
};

Scratch& scratch() {
  static Scratch instance;
  return instance;
}

// Writes the example scene `name` into the scratch folder unless it is there already.
void writeOnce(const std::string& name) {
  static std::set<std::string> written;
  if (written.count(name)) return;
  std::vector<ExampleScene> all = goodScenes();
  for (ExampleScene& scene : comeshScenes()) all.push_back(std::move(scene));
  for (const ExampleScene& scene : all)
    if (scene.name == name) {
      writeScene(scene, scratch().folder());
      written.insert(name);
      return;
    }
  throw std::invalid_argument("no example scene named " + name);
}

}  // namespace

CommandRun inbetween(const std::vector<std::string>& args, const std::string& prefix) {
  std::vector<std::string> words{INBETWEEN_CLI};
  words.insert(words.end(), args.begin(), args.end());
  return runCommand((prefix.empty() ? "" : prefix + " ") + commandLine(words));
}

std::vector<nlohmann::json> jsonLines(const std::string& out) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    INFO("stdout line: " << line);
    REQUIRE(nlohmann::json::accept(line));
    lines.push_back(nlohmann::json::parse(line));
  }
  return lines;
}

std::string exampleScene(const std::string& name) {
  writeOnce(name);
  return (fs::path(scratch().folder()) / name / "scene.json").string();
}

std::string badScene(const std::string& file) {
  static bool written = false;
  if (!written) {
    writeOnce("square-arch-notch");
    writeBadScenes(scratch().folder());
    written = true;
  }
  const fs::path path = fs::path(scratch().folder()) / "bad" / file;
  if (!fs::exists(path)) throw std::invalid_argument("no bad scene named " + file);
  return path.string();
}

std::string scratchPath(const std::string& relative) { return (fs::path(scratch().folder()) / relative).string(); }

bool exists(const std::string& path) { return fs::exists(path); }

}  // namespace test
