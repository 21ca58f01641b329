// The parameter table (solver/scene/parameters.h) against everything that reads it: the scene
// parser, --set's text, the JSON a save writes, and docs/parameters.md.
#include "scene/parameter_json.h"
#include "scene/parameters.h"
#include "scene/scene.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "testkit/command_run.h"
#include "testkit/errors.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

using namespace ib;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

using ::test::inputError;

namespace {

const std::string kScene = std::string(INBETWEEN_ASSETS) + "/square-arch-stretch/scene.json";

// A value the parameter takes that is not its default: inside the range, another word, the
// other state, a grey.
double otherValue(const ParameterSpec& spec) {
  switch (spec.kind) {
    case ParameterKind::kToggle: return spec.defaultValue == 0 ? 1 : 0;
    case ParameterKind::kChoice: return spec.defaultValue == 0 ? 1 : 0;
    case ParameterKind::kColor: return 0x808080;
    case ParameterKind::kInteger: return spec.defaultValue == spec.max ? spec.max - 1 : spec.defaultValue + 1;
    case ParameterKind::kNumber: break;
  }
  const double candidate = spec.logScale && spec.max > 0 ? std::sqrt(std::max(spec.min, 1e-9) * spec.max)
                                                         : spec.min + 0.375 * (spec.max - spec.min);
  return candidate == spec.defaultValue ? spec.min + 0.625 * (spec.max - spec.min) : candidate;
}


}  // namespace

TEST_CASE("parameter table: every row has a unique name, a meaning, a default it accepts, and a scene field unless the player's own") {
  std::set<std::string> names, fields;
  for (const ParameterSpec& spec : parameterTable()) {
    INFO(spec.name);
    CHECK(names.insert(spec.name).second);
    CHECK_FALSE(spec.meaning.empty());
    CHECK_NOTHROW(checkParameterValue(spec, spec.defaultValue, spec.name));
    if (spec.field.empty()) {
      CHECK(spec.live);  // the player's own: kappa_scale, dynamics
      CHECK(spec.get == nullptr);
    } else {
      CHECK(spec.get != nullptr);
      CHECK(spec.set != nullptr);
      CHECK(fields.insert(spec.field + (spec.component < 0 ? "" : std::to_string(spec.component))).second);
    }
    if (spec.live) CHECK(spec.invalidates != Invalidates::kMultimesh);
    if (spec.kind == ParameterKind::kChoice) CHECK(spec.choices.size() >= 2);
  }
  CHECK(names.size() >= 30);
}

TEST_CASE("parameter table: every field the file holds is read into the scene as written, through the table's row") {
  const Json original = Json::parse(readFile(kScene));
  for (const ParameterSpec& spec : parameterTable()) {
    if (spec.field.empty()) continue;
    DYNAMIC_SECTION(spec.name) {
      const double value = otherValue(spec);
      Json edited = original;
      writeParameter(edited, spec, value);
      CHECK(parameterIn(edited, spec) == value);
      const Scene scene = parseScene(edited.dump(), kScene);
      CHECK(spec.get(scene) == value);
      // Every other parameter kept the file's value.
      const Scene before = parseScene(original.dump(), kScene);
      for (const ParameterSpec& other : parameterTable())
        if (other.get && &other != &spec) CHECK(other.get(scene) == other.get(before));
      removeParameter(edited, spec);
      CHECK(spec.get(parseScene(edited.dump(), kScene)) == spec.defaultValue);
    }
  }
}

TEST_CASE("parameter table: a value out of a row's range in the file names the file, the field and the range") {
  for (const ParameterSpec& spec : parameterTable()) {
    if (spec.field.empty() || (spec.kind != ParameterKind::kNumber && spec.kind != ParameterKind::kInteger)) continue;
    DYNAMIC_SECTION(spec.name) {
      Json edited = Json::parse(readFile(kScene));
      const double beyond = spec.max + (spec.max - spec.min + 1);
      if (spec.component < 0) {
        const size_t dot = spec.field.find('.');
        Json& holder = dot == std::string::npos ? edited : edited[spec.field.substr(0, dot)];
        holder[spec.field.substr(dot == std::string::npos ? 0 : dot + 1)] = beyond;
      } else {
        writeParameter(edited, spec, spec.max);
        Json& point = edited["dynamics"][spec.field.substr(spec.field.find('.') + 1)];
        point[static_cast<size_t>(spec.component)] = beyond;
      }
      const std::string message = inputError([&] { parseScene(edited.dump(), kScene); });
      const std::string key = spec.field.substr(spec.field.find('.') + 1);
      CHECK_THAT(message, Catch::StartsWith("scene.json: ") && Catch::Contains(key + ": ") &&
                              Catch::Contains(formatParameterRange(spec)));
    }
  }
}

TEST_CASE("parameter table: text as --set gives it reads back as the value it formats") {
  for (const ParameterSpec& spec : parameterTable()) {
    INFO(spec.name);
    const double value = otherValue(spec);
    CHECK(parseParameterText(spec, formatParameterValue(spec, value), "--set") == value);
  }
  CHECK(parseParameterText(parameter("tau"), "1e-9", "--set") == 1e-9);
  CHECK(formatParameterValue(parameter("fps"), 23.976023976) == "23.976023976");  // every digit that counts
  CHECK(formatParameterValue(parameter("tau"), 1e-3) == "0.001");
  CHECK_THAT(inputError([] { checkParameterValue(parameter("non_overlap"), 0.5, "x"); }),
             Catch::Contains("x: 0.5 is out of range on or off"));
  CHECK(parseParameterText(parameter("non_overlap"), "on", "--set") == 1);
  CHECK(parseParameterText(parameter("metric"), "per_key", "--set") == 1);
  CHECK(parseParameterText(parameter("paper_color"), "ff8800", "--set") == 0xff8800);
  CHECK(parseParameterText(parameter("paper_color"), "none", "--set") == -1);
  CHECK(parseParameterText(parameter("edge_length"), "0", "--set") == 0);  // 0 follows the drawings
  CHECK_THAT(inputError([] { parseParameterText(parameter("edge_length"), "0.25", "--set"); }),
             Catch::Contains("0 (follow the drawings) or [0.5, 1e+06]"));
  CHECK_THAT(inputError([] { parseParameterText(parameter("alpha_threshold"), "12.5", "--set"); }),
             Catch::Contains("whole numbers [1, 255]"));
  CHECK_THAT(inputError([] { parameter("lamda"); }), Catch::Contains("did you mean \"lambda\""));
  CHECK_THAT(inputError([] { parameter("gravity-y"); }), Catch::Contains("did you mean \"gravity_y\""));
  CHECK_THAT(inputError([] { parameter("solver.tua"); }), Catch::Contains("did you mean \"solver.tau\""));
  CHECK_THAT(inputError([] { parameter("dynamics.gravity.z"); }), Catch::Contains("did you mean \"dynamics.gravity.x\""));
  CHECK(&parameter("solver.tau") == &parameter("tau"));
  CHECK(&parameter("dynamics.gravity.y") == &parameter("gravity_y"));
}

TEST_CASE("parameter table: docs/parameters.md holds the table `inbetween parameters --markdown` prints") {
  const std::string doc = readFile(std::string(INBETWEEN_SOURCE_DIR) + "/docs/parameters.md");
  const test::CommandRun run = test::runCommand(std::string(INBETWEEN_CLI) + " parameters --markdown");
  REQUIRE(run.code == 0);
  const std::string begin = "<!-- parameters: begin -->\n", end = "<!-- parameters: end -->";
  const size_t from = doc.find(begin), to = doc.find(end);
  REQUIRE(from != std::string::npos);
  REQUIRE(to != std::string::npos);
  INFO("regenerate with: inbetween parameters --markdown");
  CHECK(doc.substr(from + begin.size(), to - from - begin.size()) == run.output);
  for (const ParameterSpec& spec : parameterTable()) CHECK_THAT(run.output, Catch::Contains("| `" + spec.name + "` |"));
}
