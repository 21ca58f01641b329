#include "testkit/example_scenes.h"

#include "core/atomic_file.h"
#include "testkit/drawings.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace test {

namespace {

constexpr int kSize = 128;  // px: every drawing is kSize x kSize

Inside ellipse(double cx, double cy, double rx, double ry) {
  return [=](double x, double y) { return std::pow((x - cx) / rx, 2) + std::pow((y - cy) / ry, 2) <= 1; };
}

Inside square() { return box(28, 28, 100, 100); }
// An arch opening downwards: a block with a cavity from its bottom edge.
Inside arch() { return subtract(box(16, 20, 112, 108), box(46, 56, 82, 108.5)); }

ExampleScene squareArchStretch() {
  return {"square-arch-stretch", R"({
  "version": 1,
  "reference": "square",
  "edge_length": 6,
  "keys": [
    {"name": "square", "drawing": "square.png",
     "features": {"top-left": [28, 28], "top-right": [100, 28], "bottom-right": [100, 100], "bottom-left": [28, 100]}},
    {"name": "arch", "drawing": "arch.png",
     "features": {"top-left": [16, 20], "top-right": [112, 20], "bottom-right": [112, 108], "bottom-left": [16, 108]}}
  ],
  "timeline": {"fps": 24, "loop": true, "marks": [
    {"time": 0, "key": "square", "ease": "ease-in"},
    {"time": 0.5, "key": "arch", "ease": "hold"},
    {"time": 1.25, "key": "arch", "ease": "ease-in-out"},
    {"time": 2, "key": "square"}
  ]},
  "dynamics": {"epsilon": 0.6, "gravity": [0, 3], "mu": 1},
  "stiffness": {"regions": [{"name": "top", "key": "square", "polygon": [[20, 20], [108, 20], [108, 50], [20, 50]],
                             "kappa": 4}]}
})",
          {{"square.png", drawShape(kSize, kSize, square())}, {"arch.png", drawShape(kSize, kSize, arch())}}};
}

ExampleScene squareArchNotch() {
  return {"square-arch-notch", R"({
  "version": 1,
  "reference": "square",
  "edge_length": 6,
  "keys": [
    {"name": "square", "drawing": "square.png",
     "features": {"top": [64, 28]},
     "cuts": [{"name": "split", "kind": "notch", "points": [[64, 100], [64, 64]]}]},
    {"name": "arch", "drawing": "arch.png",
     "features": {"top": [64, 20], "split.left": [46, 108], "split.right": [82, 108], "split.tip": [64, 56]}}
  ],
  "timeline": {"fps": 24, "loop": true, "marks": [
    {"time": 0, "key": "square", "ease": "ease-in-out"},
    {"time": 1, "key": "arch", "ease": {"cubic_bezier": [0.3, 0, 0.2, 1]}},
    {"time": 2, "key": "square"}
  ]}
})",
          {{"square.png", drawShape(kSize, kSize, square())}, {"arch.png", drawShape(kSize, kSize, arch())}}};
}

// A slit in the disc opens into the ring's hole; the outer loops have no features at all.
ExampleScene discRing() {
  return {"disc-ring", R"({
  "version": 1,
  "reference": "disc",
  "edge_length": 6,
  "keys": [
    {"name": "disc", "drawing": "disc.png",
     "cuts": [{"name": "hole", "kind": "slit", "points": [[56, 64], [72, 64]]}]},
    {"name": "ring", "drawing": "ring.png",
     "features": {"hole.start": [42, 64], "hole.end": [86, 64]}}
  ]
})",
          {{"disc.png", drawShape(kSize, kSize, disc(64, 64, 46))},
           {"ring.png", drawShape(kSize, kSize, subtract(disc(64, 64, 46), disc(64, 64, 22)))}}};
}

// A split from top to bottom separates one cell into two. Walking the cut downwards, its left
// side (screen +x) becomes the right cell.
ExampleScene cellSplit() {
  return {"cell-split", R"({
  "version": 1,
  "reference": "one",
  "edge_length": 6,
  "keys": [
    {"name": "one", "drawing": "one.png",
     "cuts": [{"name": "division", "kind": "split", "points": [[64, 38], [64, 90]]}]},
    {"name": "two", "drawing": "two.png",
     "features": {"division.start.left": [72.4, 48.4], "division.end.left": [72.4, 79.6],
                  "division.start.right": [55.6, 48.4], "division.end.right": [55.6, 79.6]}}
  ]
})",
          {{"one.png", drawShape(kSize, kSize, ellipse(64, 64, 50, 26))},
           {"two.png", drawShape(kSize, kSize, unite(disc(40, 64, 22), disc(88, 64, 22)))}}};
}

// Two concentric rings become two offset, squashed rings: four loops, none with features.
ExampleScene nestedRings() {
  const Inside first = unite(subtract(disc(64, 64, 58), disc(64, 64, 44)), subtract(disc(64, 64, 32), disc(64, 64, 18)));
  const Inside second = unite(subtract(ellipse(62, 66, 60, 50), ellipse(62, 66, 47, 38)),
                              subtract(ellipse(68, 66, 34, 26), ellipse(68, 66, 20, 13)));
  return {"nested-rings", R"({
  "version": 1,
  "reference": "round",
  "edge_length": 6,
  "keys": [
    {"name": "round", "drawing": "round.png"},
    {"name": "squashed", "drawing": "squashed.png"}
  ]
})",
          {{"round.png", drawShape(kSize, kSize, first)}, {"squashed.png", drawShape(kSize, kSize, second)}}};
}

}  // namespace

std::vector<ExampleScene> goodScenes() {
  return {squareArchStretch(), squareArchNotch(), discRing(), cellSplit(), nestedRings()};
}

void writeScene(const ExampleScene& scene, const std::string& folder) {
  const std::filesystem::path dir = std::filesystem::path(folder) / scene.name;
  std::filesystem::create_directories(dir);
  ib::writeFileAtomically((dir / "scene.json").string(), scene.json);
  for (const auto& [file, image] : scene.drawings) ib::writePng((dir / file).string(), image);
}

std::vector<std::string> bundledSceneFiles(const std::string& folder) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (std::filesystem::exists(entry.path() / "scene.json")) files.push_back((entry.path() / "scene.json").string());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::pair<std::string, std::string>> writeBadScenes(const std::string& folder) {
  const std::filesystem::path dir = std::filesystem::path(folder) / "bad";
  std::filesystem::create_directories(dir);
  ib::writeFileAtomically((dir / "corrupt.png").string(), "\x89PNG\r\n\x1a\n this is not a PNG");
  ib::writePng((dir / "empty.png").string(), drawShape(kSize, kSize, [](double, double) { return false; }));
  // The square with a hole in its middle, the square with a second piece beside it, the square on a wider canvas.
  ib::writePng((dir / "holed.png").string(), drawShape(kSize, kSize, subtract(square(), box(54, 54, 74, 74))));
  ib::writePng((dir / "two-pieces.png").string(), drawShape(kSize, kSize, unite(square(), box(106, 8, 122, 24))));
  ib::writePng((dir / "wide.png").string(), drawShape(kSize + 12, kSize, square()));
  const std::string square = "../square-arch-notch/square.png", archPng = "../square-arch-notch/arch.png";
  const auto scene = [&](const std::string& squareDrawing, const std::string& squareExtra, const std::string& archFeatures) {
    return R"({"version": 1, "reference": "square", "edge_length": 6, "keys": [
      {"name": "square", "drawing": ")" + squareDrawing + R"(", "features": {"top": [64, 28]},
       "cuts": [{"name": "split", "kind": "notch", "points": [[64, 100], )" + squareExtra + R"(]}]},
      {"name": "arch", "drawing": ")" + archPng + R"(", "features": {)" + archFeatures + R"(}}]})";
  };
  const std::string archOk = R"("top": [64, 20], "split.left": [46, 108], "split.right": [82, 108], "split.tip": [64, 56])";
  // The good scene with one more top-level field.
  const auto with = [&](const std::string& field, const std::string& value) {
    nlohmann::json j = nlohmann::json::parse(scene(square, "[64, 64]", archOk));
    j[field] = nlohmann::json::parse(value);
    return j.dump();
  };
  // Two keys without features: the square and `other`.
  const auto pair = [&](const std::string& other) {
    return R"({"version": 1, "edge_length": 6, "keys": [{"name": "square", "drawing": ")" + square +
           R"("}, {"name": "other", "drawing": ")" + other + R"("}]})";
  };
  // The good scene with one more field in key `key` (or in its first cut).
  const auto keyWith = [&](int key, bool inCut, const std::string& field, const std::string& value) {
    nlohmann::json j = nlohmann::json::parse(scene(square, "[64, 64]", archOk));
    (inCut ? j["keys"][key]["cuts"][0] : j["keys"][key])[field] = nlohmann::json::parse(value);
    return j.dump();
  };
  const std::vector<std::tuple<std::string, std::string, std::string>> bad = {
      {"missing-drawing", scene("no-such-drawing.png", "[64, 64]", archOk), "no-such-drawing.png"},
      {"corrupt-png", scene("corrupt.png", "[64, 64]", archOk), "corrupt.png"},
      {"empty-drawing", scene("empty.png", "[64, 64]", archOk), "empty drawing"},
      {"malformed-json", "{\"version\": 1, \"keys\": [", "malformed JSON"},
      {"unknown-field", R"({"version": 1, "colour": "red", "keys": [{"name": "a", "drawing": "x.png"}]})",
       "unknown field \"colour\""},
      {"missing-feature", scene(square, "[64, 64]", R"("top": [64, 20], "split.left": [46, 108], "split.right": [82, 108])"),
       "does not place feature \"split.tip\""},
      {"feature-far-off", scene(square, "[64, 64]",
                                R"("top": [64, 70], "split.left": [46, 108], "split.right": [82, 108], "split.tip": [64, 56])"),
       "feature \"top\""},
      {"cut-leaves-shape", scene(square, "[64, 64], [64, 10]", archOk), "leaves the shape"},
      {"loops-do-not-match", scene(square, "[64, 64]",
                                   R"("top": [64, 20], "split.left": [82, 108], "split.right": [46, 108], "split.tip": [64, 56])"),
       "loops do not match"},
      {"timeline-unknown-key", with("timeline", R"({"marks": [{"time": 0, "key": "circle"}]})"),
       "timeline: mark 1: key: \"circle\" is not a key"},
      {"dynamics-out-of-range", with("dynamics", R"({"epsilon": 3})"), "dynamics: epsilon: 3"},
      {"missing-stiffness-image", with("stiffness", R"({"image": {"key": "square", "path": "no-such-stiffness.png"}})"),
       "no-such-stiffness.png"},
      // The keys' topology differs, a plain feature with a dot, unknown fields inside objects.
      {"extra-hole", pair("holed.png"), "key \"other\" has a hole that key \"square\" does not"},
      {"extra-piece", pair("two-pieces.png"), "key \"other\" has a piece that key \"square\" does not"},
      {"dotted-feature", scene(square, "[64, 64]", archOk + R"(, "a.b": [20, 64])"),
       "key \"arch\": feature \"a.b\": names with a '.' are reserved"},
      {"unknown-field-in-key", keyWith(1, false, "colour", "\"red\""), "key \"arch\": unknown field \"colour\""},
      {"unknown-field-in-cut", keyWith(0, true, "width", "2"), "key \"square\": cut \"split\": unknown field \"width\""},
      {"unknown-field-in-mark",
       with("timeline", R"({"marks": [{"time": 0, "key": "square", "easing": "linear"}, {"time": 1, "key": "arch"}]})"),
       "timeline: mark 1: unknown field \"easing\""},
      // Odd but accepted (exit code 0 with a note).
      {"canvas-sizes", pair("wide.png"), "keys have different canvas sizes (128x128 for \"square\", 140x128 for \"other\")"},
      {"one-key", R"({"version": 1, "edge_length": 6, "keys": [{"name": "square", "drawing": ")" + square + R"("}]})",
       "one key (\"square\"): the animation is a still"},
  };
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& [name, text, message] : bad) {
    const std::string file = (dir / (name + ".json")).string();
    ib::writeFileAtomically(file, text);
    files.push_back({file, message});
  }
  return files;
}

}  // namespace test
