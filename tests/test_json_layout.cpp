// rewriteJson (core/json_layout.h): an edited scene written back in the layout it was read in, so
// that one edit is a small diff. Expectations are texts written here; the bundled scenes (assets/
// and tests/drawn) are written back unchanged. Damaged texts and random edits:
// test_json_layout_random.cpp.
#include "json_layout_support.h"

#include <string>

using ib::rewriteJson;
using namespace test;

namespace {

// The example of the scene format: one-line objects inside a multi-line layout.
const std::string kScene = R"({
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
}
)";

// The layout of a scene written by nlohmann's dump(1): every value on its own line.
const std::string kExpanded = R"({
 "version": 1,
 "solver": {
  "tau": 1e-07
 },
 "keys": [
  {
   "name": "square",
   "features": {
    "top": [
     256,
     166
    ],
    "tip": [
     256,
     271
    ]
   },
   "cuts": [
    {
     "name": "split",
     "points": [
      [
       256,
       369
      ],
      [
       256,
       270
      ]
     ]
    }
   ]
  }
 ]
})";

// `text` with its one occurrence of `from` replaced by `to` (the expectation of an edit).
std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  REQUIRE(text.find(from, at + 1) == std::string::npos);
  return text.substr(0, at) + to + text.substr(at + from.size());
}

}  // namespace


TEST_CASE("json layout: a document written back unchanged is the original text, byte for byte") {
  const std::vector<fs::path> files = sceneFiles();
  CHECK(files.size() >= 30);
  for (const fs::path& file : files) {
    INFO(file.string());
    const std::string text = readFile(file);
    CHECK(rewriteJson(text, Json::parse(text)) == text);
  }
  for (const std::string& text :
       {kScene, kExpanded, std::string("{}"), std::string("\xEF\xBB\xBF  {\"a\" :1 ,\"b\":[ ]}\r\n\r\n"),
        std::string("{\"a\\u00e9\\\"\": \"x\\n\\u0041\", \"n\": -0.0e+00, \"m\": 1E3, \"t\": [true, false, null]}"),
        std::string("{\"a\": 1, \"b\": 2, \"a\": 3}")}) {
    INFO(text);
    CHECK(rewriteJson(text, Json::parse(text)) == text);
  }
}

TEST_CASE("json layout: moving one feature point changes only that point's text") {
  const std::string moved = edited(kScene, [](Json& s) { s["keys"][1]["features"]["split.left"][0] = 47; });
  CHECK(moved == replaced(kScene, "\"split.left\": [46, 108]", "\"split.left\": [47, 108]"));
  const LineWindow window = changedLines(kScene, moved);
  CHECK(window.before == std::vector<std::string>{
                             R"(     "features": {"top": [64, 20], "split.left": [46, 108], "split.right": [82, 108], "split.tip": [64, 56]}})"});
  CHECK(window.after == std::vector<std::string>{
                            R"(     "features": {"top": [64, 20], "split.left": [47, 108], "split.right": [82, 108], "split.tip": [64, 56]}})"});

  CHECK(edited(kExpanded, [](Json& s) { s["keys"][0]["features"]["top"][1] = 170.5; }) ==
        replaced(kExpanded, "     166\n", "     170.5\n"));

  // On every bundled scene: the first feature of the first key that has one.
  for (const fs::path& file : sceneFiles()) {
    INFO(file.string());
    const std::string text = readFile(file);
    std::string name;
    const std::string result = edited(text, [&](Json& s) {
      for (Json& key : s["keys"])
        if (key.contains("features") && !key["features"].empty()) {
          name = key["features"].begin().key();
          key["features"].begin().value()[0] = 1234.5;
          return;
        }
    });
    if (name.empty()) continue;
    const LineWindow window = changedLines(text, result);
    REQUIRE(window.after.size() == 1);
    REQUIRE(window.before.size() == 1);
    CHECK(window.after[0].find("1234.5") != std::string::npos);
  }
}

TEST_CASE("json layout: a member added to a one-line object follows its last member on that line after ', '") {
  CHECK(edited(kScene, [](Json& s) { s["keys"][0]["features"]["bottom"] = {64, 100}; }) ==
        replaced(kScene, R"("features": {"top": [64, 28]},)", R"("features": {"top": [64, 28], "bottom": [64, 100]},)"));
  CHECK(edited(kScene, [](Json& s) { s["timeline"]["speed"] = 0.5; }) ==
        replaced(kScene, "  ]}\n}", "  ], \"speed\": 0.5}\n}"));
}

TEST_CASE("json layout: a member added to a multi-line object goes on a new line at the previous member's indentation") {
  CHECK(edited(kScene, [](Json& s) { s["solver"] = {{"tau", 1e-7}}; }) ==
        replaced(kScene, "  ]}\n}\n", "  ]},\n  \"solver\": {\"tau\": 1e-07}\n}\n"));
  CHECK(edited(kExpanded, [](Json& s) { s["keys"][0]["features"]["bottom"] = {256, 400}; }) ==
        replaced(kExpanded, "    ]\n   },\n   \"cuts\"", "    ],\n    \"bottom\": [256, 400]\n   },\n   \"cuts\""));
  CHECK(edited(kExpanded, [](Json& s) { s["solver"]["alpha"] = 0.5; }) ==
        replaced(kExpanded, "  \"tau\": 1e-07\n", "  \"tau\": 1e-07,\n  \"alpha\": 0.5\n"));
  // In a key written over two lines, the new member lines up with the one before it.
  CHECK(edited(kScene, [](Json& s) { s["keys"][1]["interior_features"] = Json::object({{"eye", {60, 40}}}); }) ==
        replaced(kScene, "[64, 56]}}\n", "[64, 56]},\n     \"interior_features\": {\"eye\": [60, 40]}}\n"));
  // Several members a line: the new one starts a line under the first member of the last line.
  const std::string pairs = "{\n  \"features\": {\"a\": [1, 2], \"b\": [3, 4],\n               \"c\": [5, 6], \"d\": [7, 8]}\n}\n";
  CHECK(edited(pairs, [](Json& s) { s["features"]["e"] = {9, 10}; }) ==
        "{\n  \"features\": {\"a\": [1, 2], \"b\": [3, 4],\n               \"c\": [5, 6], \"d\": [7, 8],\n"
        "               \"e\": [9, 10]}\n}\n");
  // A member removed and one added in its place (the last) take its line.
  CHECK(edited(kScene, [](Json& s) {
          s["keys"][1].erase("features");
          s["keys"][1]["speed"] = 2;
        }) == replaced(kScene, "\"features\": {\"top\": [64, 20], \"split.left\": [46, 108], \"split.right\": [82, 108], "
                               "\"split.tip\": [64, 56]}}",
                       "\"speed\": 2}"));
}

TEST_CASE("json layout: removing the first, a middle or the last member takes its separator with it") {
  const auto without = [](const std::string& text, const std::string& pointer, const std::string& key) {
    return edited(text, [&](Json& s) { s[Json::json_pointer(pointer)].erase(key); });
  };
  const std::string features = R"({"top": [64, 20], "split.left": [46, 108], "split.right": [82, 108], "split.tip": [64, 56]})";
  CHECK(without(kScene, "/keys/1/features", "top") ==
        replaced(kScene, features, R"({"split.left": [46, 108], "split.right": [82, 108], "split.tip": [64, 56]})"));
  CHECK(without(kScene, "/keys/1/features", "split.right") ==
        replaced(kScene, features, R"({"top": [64, 20], "split.left": [46, 108], "split.tip": [64, 56]})"));
  CHECK(without(kScene, "/keys/1/features", "split.tip") ==
        replaced(kScene, features, R"({"top": [64, 20], "split.left": [46, 108], "split.right": [82, 108]})"));
  CHECK(without(kScene, "", "version") == replaced(kScene, "{\n  \"version\": 1,\n", "{\n"));
  CHECK(without(kScene, "", "edge_length") == replaced(kScene, "  \"edge_length\": 6,\n", ""));
  CHECK(without(kScene, "", "timeline") == kScene.substr(0, kScene.find(",\n  \"timeline\"")) + "\n}\n");
  // The member between two lines goes with the line break and indentation before it.
  CHECK(without(kScene, "/keys/0", "features") == replaced(kScene, "\n     \"features\": {\"top\": [64, 28]},", ""));
  // The last member of a key written over two lines: the previous one ends the object.
  CHECK(without(kScene, "/keys/1", "features") ==
        replaced(kScene, "\"arch.png\",\n     \"features\": " + features + "}", "\"arch.png\"}"));
  CHECK(without(kExpanded, "/keys/0/features", "top") == replaced(kExpanded, "    \"top\": [\n     256,\n     166\n    ],\n", ""));
}

TEST_CASE("json layout: inserting or removing an array element keeps the other elements' text") {
  const auto insertPoint = [](Json& s) {
    Json& points = s["keys"][0]["cuts"][0]["points"];
    points.insert(points.begin() + 1, Json{70, 80});
  };
  CHECK(edited(kScene, insertPoint) == replaced(kScene, "[[64, 100], [64, 64]]", "[[64, 100], [70, 80], [64, 64]]"));
  CHECK(edited(kExpanded, insertPoint) ==
        replaced(kExpanded, "       369\n      ],\n", "       369\n      ],\n      [70, 80],\n"));
  // A timeline mark between two others.
  CHECK(edited(kScene, [](Json& s) {
          Json& marks = s["timeline"]["marks"];
          marks.insert(marks.begin() + 2, Json{{"time", 1.5}, {"key", "square"}});
        }) == replaced(kScene, "    {\"time\": 2,", "    {\"time\": 1.5, \"key\": \"square\"},\n    {\"time\": 2,"));
  // A mark in front: the first element's text moves after the new one.
  CHECK(edited(kScene, [](Json& s) {
          Json& marks = s["timeline"]["marks"];
          marks.insert(marks.begin(), Json{{"time", -1}, {"key", "arch"}});
        }) == replaced(kScene, "\"marks\": [\n", "\"marks\": [\n    {\"time\": -1, \"key\": \"arch\"},\n"));
  // Removing the first key, the middle mark, the last cut point.
  CHECK(edited(kScene, [](Json& s) { s["keys"].erase(0); }) ==
        replaced(kScene,
                 "    {\"name\": \"square\", \"drawing\": \"square.png\",\n"
                 "     \"features\": {\"top\": [64, 28]},\n"
                 "     \"cuts\": [{\"name\": \"split\", \"kind\": \"notch\", \"points\": [[64, 100], [64, 64]]}]},\n",
                 ""));
  CHECK(edited(kScene, [](Json& s) { s["timeline"]["marks"].erase(1); }) ==
        replaced(kScene, "    {\"time\": 1, \"key\": \"arch\", \"ease\": {\"cubic_bezier\": [0.3, 0, 0.2, 1]}},\n", ""));
  CHECK(edited(kExpanded, [](Json& s) { s["keys"][0]["cuts"][0]["points"].erase(1); }) ==
        replaced(kExpanded, "       369\n      ],\n      [\n       256,\n       270\n      ]\n", "       369\n      ]\n"));
  // One changed element of three equal ones is rewritten in its place.
  CHECK(edited("{\"a\": [1, 1, 1]}", [](Json& s) { s["a"][1] = 2; }) == "{\"a\": [1, 2, 1]}");
}

TEST_CASE("json layout: renaming a key (rebuilding the object in order) changes only the line of that member") {
  const auto renamed = [](const std::string& text, const std::string& pointer, const std::string& from,
                          const std::string& to) {
    return edited(text, [&](Json& s) {
      Json rebuilt = Json::object();
      for (auto it = s[Json::json_pointer(pointer)].begin(); it != s[Json::json_pointer(pointer)].end(); ++it)
        rebuilt[it.key() == from ? to : it.key()] = it.value();
      s[Json::json_pointer(pointer)] = rebuilt;
    });
  };
  CHECK(renamed(kScene, "/keys/1/features", "split.tip", "split.point") ==
        replaced(kScene, "\"split.tip\": [64, 56]", "\"split.point\": [64, 56]"));
  CHECK(renamed(kScene, "/keys/1/features", "top", "crown") == replaced(kScene, "\"top\": [64, 20]", "\"crown\": [64, 20]"));
  // A value over several lines keeps them.
  const std::string crown = renamed(kExpanded, "/keys/0/features", "top", "crown");
  CHECK(crown == replaced(kExpanded, "\"top\": [\n", "\"crown\": [\n"));
  CHECK(changedLines(kExpanded, crown).after == std::vector<std::string>{"    \"crown\": ["});
  CHECK(renamed(kScene, "", "edge_length", "edge") == replaced(kScene, "\"edge_length\": 6,", "\"edge\": 6,"));
}

TEST_CASE("json layout: a number spelled 1e-3 or a string with escapes keeps its spelling when another value changes") {
  const std::string text = "{\n  \"solver\": {\"tau\": 1e-3, \"alpha\": 0.5, \"steps\": 1.0E2},\n  \"fps\": 24\n}\n";
  CHECK(edited(text, [](Json& s) { s["solver"]["alpha"] = 0.25; }) ==
        "{\n  \"solver\": {\"tau\": 1e-3, \"alpha\": 0.25, \"steps\": 1.0E2},\n  \"fps\": 24\n}\n");
  CHECK(edited(text, [](Json& s) { s["fps"] = 12; }) ==
        "{\n  \"solver\": {\"tau\": 1e-3, \"alpha\": 0.5, \"steps\": 1.0E2},\n  \"fps\": 12\n}\n");
  // A value set to what it was (1e-3 == 0.001) keeps its spelling too.
  CHECK(edited(text, [](Json& s) { s["solver"]["tau"] = 0.001; }) == text);
  CHECK(edited(R"({"a\u00e9\"": "x\n\u0041", "m": 1E3})", [](Json& s) { s["m"] = 5; }) ==
        R"({"a\u00e9\"": "x\n\u0041", "m": 5})");
}

TEST_CASE("json layout: new values are written on one line, broken over lines when longer than 100 characters") {
  CHECK(edited(kScene, [](Json& s) { s["edge_length"] = {{"min", 4}, {"max", 8}}; }) ==
        replaced(kScene, "\"edge_length\": 6,", "\"edge_length\": {\"min\": 4, \"max\": 8},"));
  Json eyes = Json::object();
  for (const char* name : {"eye_left", "eye_right", "mouth", "nose", "chin"})
    eyes[name] = {{"at", {50, 80}}, {"radius", 12}};
  CHECK(edited(kScene, [&](Json& s) { s["keys"][0]["interior_features"] = eyes; }) ==
        replaced(kScene, "[[64, 100], [64, 64]]}]},\n",
                 "[[64, 100], [64, 64]]}],\n"
                 "     \"interior_features\": {\n"
                 "       \"eye_left\": {\"at\": [50, 80], \"radius\": 12},\n"
                 "       \"eye_right\": {\"at\": [50, 80], \"radius\": 12},\n"
                 "       \"mouth\": {\"at\": [50, 80], \"radius\": 12},\n"
                 "       \"nose\": {\"at\": [50, 80], \"radius\": 12},\n"
                 "       \"chin\": {\"at\": [50, 80], \"radius\": 12}\n"
                 "     }},\n"));
  // A string replaced by a number, a number by an array: each in its place.
  CHECK(edited(kScene, [](Json& s) {
          s["reference"] = 3;
          s["version"] = {1, 2};
        }) == replaced(replaced(kScene, "\"reference\": \"square\"", "\"reference\": 3"), "\"version\": 1",
                       "\"version\": [1, 2]"));
}

TEST_CASE("json layout: lines added to a file with CRLF line ends end with CRLF too") {
  const std::string text = "{\r\n  \"a\": 1\r\n}\r\n";
  CHECK(edited(text, [](Json& s) { s["b"] = 2; }) == "{\r\n  \"a\": 1,\r\n  \"b\": 2\r\n}\r\n");
}
