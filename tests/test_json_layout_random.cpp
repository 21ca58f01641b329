// rewriteJson (core/json_layout.h) on texts it was not made for (repeated keys, a non-object,
// deep nesting, damaged scenes) and under 200 seeded random edits of every bundled scene: the
// result parses to the edited value, and only the edited values' lines change.
#include "json_layout_support.h"

#include <random>
#include <string>
#include <vector>

using ib::rewriteJson;
using namespace test;

namespace {

// Every value in v, v first.
void collectValues(Json& v, std::vector<Json*>& all) {
  all.push_back(&v);
  if (v.is_object() || v.is_array())
    for (Json& part : v) collectValues(part, all);
}

}  // namespace

TEST_CASE("json layout: an object with a repeated key keeps the text of the value nlohmann read (the last)") {
  CHECK(edited("{\"a\": 1, \"b\": 2, \"a\": 3}", [](Json& s) { s["b"] = 5; }) == "{\"a\": 3, \"b\": 5}");
}

TEST_CASE("json layout: an original that is not a JSON object gives updated.dump(2) and a line break") {
  const Json updated = Json::parse(R"({"a": [1, 2], "b": {"c": "d"}})");
  const std::string expected = "{\n  \"a\": [\n    1,\n    2\n  ],\n  \"b\": {\n    \"c\": \"d\"\n  }\n}\n";
  for (const std::string& original :
       {std::string(), std::string("not json"), std::string("[1, 2]"), std::string("\"text\""), std::string("3"),
        std::string("{\"a\": 1"), std::string("{\"a\": 01}"), std::string("{\"a\": 1.}"), std::string("{\"a\": .5}"),
        std::string("{\"a\": +1}"), std::string("{\"a\": 1,}"), std::string("{\"a\" 1}"), std::string("{'a': 1}"),
        std::string("{\"a\": \"\x01\"}"), std::string("{\"a\": \"\\x\"}"), std::string("{\"a\": \"\\u12\"}"),
        std::string("{\"a\": \"\xff\"}"), std::string("{\"a\": 1e999}"), std::string("{\"a\": tru}"), std::string("{} {}"),
        std::string("{\"a\": 1}\0", 9), std::string("{\"a\": 1} // note")}) {
    INFO(original);
    CHECK(rewriteJson(original, updated) == expected);
  }
}

TEST_CASE("json layout: deeply nested or broken text neither crashes nor blows the stack") {
  const Json updated = {{"a", 1}};
  const std::string expected = "{\n  \"a\": 1\n}\n";
  CHECK(rewriteJson(std::string(1000000, '['), updated) == expected);
  CHECK(rewriteJson(std::string(1000000, '{'), updated) == expected);
  std::string deep;
  for (int i = 0; i < 200000; ++i) deep += "{\"a\":";
  CHECK(rewriteJson(deep, updated) == expected);
  deep += "1" + std::string(200000, '}');
  CHECK(rewriteJson(deep, updated) == expected);
  // 511 arrays in an object are read (the layout is kept); 600 are too deep.
  const std::string kept = "{\"a\":" + std::string(511, '[') + std::string(511, ']') + "}";
  CHECK(rewriteJson(kept, Json::parse(kept)) == kept);
  const std::string tooDeep = "{\"a\":" + std::string(600, '[') + std::string(600, ']') + "}";
  CHECK(rewriteJson(tooDeep, updated) == expected);
}

TEST_CASE("json layout: damaged scene texts are written back as they are when valid, else fall back to dump(2)") {
  std::mt19937 random(20240611);
  const std::string alphabet = "{}[],:\"\\ \n0123456789.-eE+tfnu";
  for (const fs::path& file : sceneFiles()) {
    INFO(file.string());
    const std::string text = readFile(file);
    for (int round = 0; round < 50; ++round) {
      std::string damaged = text;
      for (int k = 1 + static_cast<int>(random() % 3); k > 0; --k) {
        const size_t at = random() % damaged.size();
        const char c = alphabet[random() % alphabet.size()];
        switch (random() % 3) {
          case 0: damaged[at] = c; break;
          case 1: damaged.insert(damaged.begin() + static_cast<long>(at), c); break;
          default: damaged.erase(at, 1 + random() % 8);
        }
      }
      INFO(damaged);
      const Json parsed = Json::parse(damaged, nullptr, false);
      if (parsed.is_object()) {
        CHECK(rewriteJson(damaged, parsed) == damaged);
        Json changed = parsed;
        changed["added"] = {1, 2};
        CHECK(Json::parse(rewriteJson(damaged, changed)) == changed);
      } else {
        const Json updated = {{"a", 1}};
        CHECK(rewriteJson(damaged, updated) == "{\n  \"a\": 1\n}\n");
      }
    }
  }
}

TEST_CASE("json layout: 200 seeded random edits on every bundled scene parse to the edited value and change only "
          "their lines") {
  enum Edit { ChangeNumber, AddMember, RemoveMember, InsertElement, RemoveElement, ReplaceByContainer, kEdits };
  std::mt19937 random(7);
  const auto pick = [&](size_t n) { return static_cast<size_t>(random() % n); };
  const auto number = [&](size_t n) { return static_cast<int>(pick(n)); };
  // A scalar, a point, a small object, an array too long for one line, or a literal.
  const auto newValue = [&]() -> Json {
    switch (pick(7)) {
      case 0:
        return number(500);
      case 1:
        return number(5000) / 10.0 + 0.5;
      case 2:
        return "s" + std::to_string(pick(100));
      case 3:
        return {number(512), number(512)};
      case 4:
        return {{"name", "n" + std::to_string(pick(100))}, {"at", {number(512), 1.5}}};
      case 5: {
        Json many = Json::array();
        for (int i = 0; i < 40; ++i) many.push_back(number(1000));
        return many;
      }
      default:
        return pick(2) ? Json(true) : Json(nullptr);
    }
  };
  const auto dumpLines = [](const Json& v) { return lines(v.dump(2)).size(); };
  std::vector<int> applied(kEdits, 0);
  for (const fs::path& file : sceneFiles()) {
    INFO(file.string());
    std::string text = readFile(file);
    Json value = Json::parse(text);
    for (int step = 0; step < 200; ++step) {
      const Edit edit = static_cast<Edit>(pick(kEdits));
      std::vector<Json*> all, candidates;
      collectValues(value, all);
      for (Json* v : all) {
        const bool fits[kEdits] = {v->is_number(),   v->is_object(), v->is_object() && !v->empty(),
                                   v->is_array(),    v->is_array() && !v->empty(), v != &value};
        if (fits[edit]) candidates.push_back(v);
      }
      if (candidates.empty()) continue;
      ++applied[edit];
      Json& target = *candidates[pick(candidates.size())];
      const bool wasScalar = !target.is_object() && !target.is_array();
      Json added;
      switch (edit) {
        case ChangeNumber:
          if (target.is_number_integer())
            target = target.get<int64_t>() + 1 + number(9);
          else
            target = target.get<double>() + 0.25;
          break;
        case AddMember:
          target["added" + std::to_string(step)] = added = newValue();
          break;
        case RemoveMember:
          target.erase(std::next(target.begin(), static_cast<long>(pick(target.size()))));
          break;
        case InsertElement:
          added = newValue();
          target.insert(target.begin() + static_cast<long>(pick(target.size() + 1)), added);
          break;
        case RemoveElement:
          target.erase(pick(target.size()));
          break;
        default:
          target = added = pick(2) ? Json{{"x", newValue()}, {"y", newValue()}} : Json{newValue(), newValue()};
      }
      const std::string result = rewriteJson(text, value);
      INFO("step " << step << ", edit " << edit << ":\n" << result);
      REQUIRE(Json::parse(result, nullptr, false) == value);
      const LineWindow window = changedLines(text, result);
      if (edit == ChangeNumber) {
        REQUIRE(window.before.size() == 1);
        REQUIRE(window.after.size() == 1);
        CHECK(window.after[0].find(target.dump()) != std::string::npos);
      } else if (edit == AddMember || edit == InsertElement) {
        CHECK(window.before.size() <= 1);
        CHECK(window.after.size() <= dumpLines(added) + 2);
      } else if (edit == RemoveMember || edit == RemoveElement) {
        CHECK(window.after.size() <= 1);
      } else if (wasScalar) {
        CHECK(window.before.size() == 1);
        CHECK(window.after.size() <= dumpLines(added));
      }
      text = result;
    }
  }
  for (int count : applied) CHECK(count > 500);
}
