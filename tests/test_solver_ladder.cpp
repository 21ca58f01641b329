// The solver's folders are the rungs of a ladder (solver/CMakeLists.txt, INBETWEEN_SOLVER_LADDER,
// lowest first): a file includes headers of its own folder and of the folders below it, never of
// one above, so each stage can be read, built and tested with only what lies under it. Read from
// the source tree as it is now (INBETWEEN_SOURCE_DIR).
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<std::string> ladder() {
  std::vector<std::string> rungs;
  std::stringstream in(INBETWEEN_SOLVER_LADDER);
  std::string rung;
  while (std::getline(in, rung, ',')) rungs.push_back(rung);
  return rungs;
}

int rankOf(const std::vector<std::string>& rungs, const std::string& folder) {
  const auto it = std::find(rungs.begin(), rungs.end(), folder);
  return it == rungs.end() ? -1 : static_cast<int>(it - rungs.begin());
}

}  // namespace

TEST_CASE("solver ladder: every folder of solver/ is a rung") {
  const std::vector<std::string> rungs = ladder();
  int folders = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(INBETWEEN_SOURCE_DIR) / "solver")) {
    if (!entry.is_directory()) continue;
    ++folders;
    INFO("solver/" << entry.path().filename().string() << " is not on the ladder: place it in INBETWEEN_SOLVER_LADDER");
    CHECK(rankOf(rungs, entry.path().filename().string()) >= 0);
  }
  CHECK(folders == static_cast<int>(rungs.size()));
}

TEST_CASE("solver ladder: no file includes a header of a folder above its own, nor of engine/ or tests/") {
  const std::vector<std::string> rungs = ladder();
  const std::regex include(R"re(^\s*#\s*include\s*"([A-Za-z0-9_]+)/[^"]+")re");
  int files = 0, includes = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(fs::path(INBETWEEN_SOURCE_DIR) / "solver")) {
    const std::string extension = entry.path().extension().string();
    if (!entry.is_regular_file() || (extension != ".h" && extension != ".cpp")) continue;
    ++files;
    const std::string folder = entry.path().parent_path().filename().string();
    const int own = rankOf(rungs, folder);
    std::ifstream in(entry.path());
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
      ++number;
      std::smatch match;
      if (!std::regex_search(line, match, include)) continue;
      ++includes;
      const int included = rankOf(rungs, match[1].str());
      INFO("solver/" << folder << "/" << entry.path().filename().string() << ":" << number << " includes " << match[1].str()
                     << "/, which is " << (included < 0 ? "not a folder of solver/" : "above " + folder + "/ on the ladder"));
      CHECK(included >= 0);
      CHECK(included <= own);
    }
  }
  CHECK(files > 50);
  CHECK(includes > 200);
}
