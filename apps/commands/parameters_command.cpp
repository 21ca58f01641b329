#include "commands/parameters_command.h"

#include "cli.h"
#include "core/error.h"
#include "scene/parameters.h"

#include <cstdio>

namespace ib {

namespace {

constexpr const char* kUsage =
    "usage: inbetween parameters [--markdown]\n"
    "\n"
    "Every parameter a scene file, --set and the player's controls take: its name (for --set\n"
    "NAME=VALUE), where the scene file holds it, unit, default, accepted values, what a change makes\n"
    "stale (nothing, the solve, or the multimesh) and what it does. Live ones are controls in\n"
    "`inbetween play`.\n"
    "\n"
    "  --markdown   the table of docs/parameters.md\n";

const char* invalidatesText(Invalidates what) {
  switch (what) {
    case Invalidates::kNothing: return "nothing";
    case Invalidates::kSolve: return "the solve";
    case Invalidates::kMultimesh: return "the multimesh";
  }
  return "";
}

std::string fieldText(const ParameterSpec& spec) {
  if (spec.field.empty()) return "(the player's own)";
  return spec.component < 0 ? spec.field : spec.field + (spec.component == 0 ? "[0]" : "[1]");
}

std::string meaningText(const ParameterSpec& spec) {
  std::string text = spec.meaning;
  if (spec.kind == ParameterKind::kChoice) {
    text += ": ";
    for (size_t i = 0; i < spec.choices.size(); ++i)
      text += (i == 0 ? "" : "; ") + spec.choices[i].word + ", " + spec.choices[i].meaning;
  }
  return text;
}

}  // namespace

int runParameters(const std::vector<std::string>& args) {
  if (cli::printHelpIfAsked(args, kUsage)) return 0;
  const cli::Arguments arguments("parameters", args, {}, {"markdown"});
  if (!arguments.positional().empty()) throw InputError("parameters: takes no SCENE (see `inbetween parameters --help`)");
  if (arguments.flag("markdown")) {
    std::printf("| name | scene field | unit | default | accepts | a change invalidates | live | meaning |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (const ParameterSpec& spec : parameterTable())
      std::printf("| `%s` | `%s` | %s | %s | %s | %s | %s | %s |\n", spec.name.c_str(), fieldText(spec).c_str(),
                  spec.unit.empty() ? "" : spec.unit.c_str(), formatParameterValue(spec, spec.defaultValue).c_str(),
                  formatParameterRange(spec).c_str(), invalidatesText(spec.invalidates), spec.live ? "yes" : "",
                  meaningText(spec).c_str());
    return 0;
  }
  for (const ParameterSpec& spec : parameterTable()) {
    std::printf("%-16s %-24s default %s%s%s, accepts %s; changes %s%s\n", spec.name.c_str(), fieldText(spec).c_str(),
                formatParameterValue(spec, spec.defaultValue).c_str(), spec.unit.empty() ? "" : " ", spec.unit.c_str(),
                formatParameterRange(spec).c_str(), invalidatesText(spec.invalidates), spec.live ? "; live in play" : "");
    std::printf("%-16s %s\n", "", meaningText(spec).c_str());
  }
  return 0;
}

}  // namespace ib
