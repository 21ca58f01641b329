// What the json layout tests share: the bundled scene files, an edit written back in its
// layout (checked to parse to the edited value), and the lines an edit changed.
#pragma once

#include "core/json_layout.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace test {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// The bytes of a file.
inline std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every bundled scene: assets/*/scene.json and the drawn test scenes, tests/drawn/*/*.json.
inline std::vector<fs::path> sceneFiles() {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(INBETWEEN_ASSETS))
    if (fs::exists(entry.path() / "scene.json")) files.push_back(entry.path() / "scene.json");
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(fs::path(INBETWEEN_ASSETS) / "../tests/drawn"))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// `text` parsed, changed by `edit` and written back in its own layout.
template <class Edit>
inline std::string edited(const std::string& text, Edit edit) {
  Json value = Json::parse(text);
  edit(value);
  const std::string result = ib::rewriteJson(text, value);
  CHECK(Json::parse(result) == value);
  return result;
}

// The lines of `text`, without their line breaks.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> all;
  std::stringstream in(text);
  std::string line;
  while (std::getline(in, line)) all.push_back(line);
  return all;
}

// The lines of `before` and of `after` between their common first lines and common last lines.
struct LineWindow {
  std::vector<std::string> before, after;
};
inline LineWindow changedLines(const std::string& before, const std::string& after) {
  const std::vector<std::string> a = lines(before), b = lines(after);
  size_t head = 0, tail = 0;
  while (head < a.size() && head < b.size() && a[head] == b[head]) ++head;
  while (tail < a.size() - head && tail < b.size() - head && a[a.size() - 1 - tail] == b[b.size() - 1 - tail]) ++tail;
  return {{a.begin() + head, a.end() - tail}, {b.begin() + head, b.end() - tail}};
}

}  // namespace test
