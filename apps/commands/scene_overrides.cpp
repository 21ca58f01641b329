#include "commands/scene_overrides.h"

#include "core/error.h"
#include "scene/parameters.h"

namespace ib::cli {

SplitSets takeSets(const std::vector<std::string>& args, const std::string& command) {
  SplitSets out;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i].rfind("--set=", 0) == 0) {
      out.sets.push_back(args[i].substr(6));
    } else if (args[i] == "--set") {
      if (i + 1 >= args.size()) throw InputError(command + ": option --set needs NAME=VALUE, e.g. --set tau=1e-5");
      out.sets.push_back(args[++i]);
    } else {
      out.rest.push_back(args[i]);
    }
  }
  return out;
}

SceneDocument sceneDocument(const std::string& scenePath, const std::vector<std::string>& sets) {
  SceneDocument document = SceneDocument::load(scenePath);
  for (const std::string& assignment : sets) document.setFromText(assignment);
  document.scene();  // throws what is wrong with the scene, naming the file, key and field
  return document;
}

std::string optionAsSet(const std::string& option, const std::string& text, const std::string& name) {
  const ParameterSpec& spec = parameter(name);
  return name + "=" + formatParameterValue(spec, parseParameterText(spec, text, option));
}

bool changesMultimesh(const std::vector<std::string>& sets, const std::string& meshFile) {
  for (const std::string& assignment : sets) {
    const ParameterSpec* spec = findParameter(assignment.substr(0, assignment.find('=')));
    if (!spec || spec->invalidates != Invalidates::kMultimesh) continue;
    if (!meshFile.empty())
      throw InputError("--set " + inQuotes(assignment) + ": " + spec->name + " shapes the multimesh, and --mesh " + meshFile +
                       " is used as it is: drop one of them (or mesh the scene with the new value: inbetween mesh)");
    return true;
  }
  return false;
}

}  // namespace ib::cli
