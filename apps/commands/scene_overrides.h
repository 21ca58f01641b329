// The scene a command works on: the file's document with the command line's overrides, `--set
// NAME=VALUE` (repeatable; any parameter of the table, scene/parameters.h) and the options that
// say the same as one (--fps is --set fps=N, --sampling is --set sampling=S).
#pragma once

#include "scene/scene_document.h"

#include <string>
#include <vector>

namespace ib::cli {

struct SplitSets {
  std::vector<std::string> sets;  // the NAME=VALUE of every --set, in order
  std::vector<std::string> rest;  // the other words
};
// Takes the --set assignments out of a command's words (the argument parser keeps one value per
// option). InputError for a --set without its NAME=VALUE, naming the command.
SplitSets takeSets(const std::vector<std::string>& args, const std::string& command);

// SCENE's document with `sets` applied in order (SceneDocument::setFromText: InputError naming
// the assignment, with "did you mean" for a mistyped name).
SceneDocument sceneDocument(const std::string& scenePath, const std::vector<std::string>& sets);

// `--OPTION TEXT` as the --set of parameter `name`: TEXT checked as the table reads it (InputError
// naming the option), e.g. --fps 12 -> "fps=12".
std::string optionAsSet(const std::string& option, const std::string& text, const std::string& name);

// Whether some assignment changes a parameter that shapes the multimesh: a multimesh cached
// beside the scene is then out of date. With `meshFile` (--mesh FILE), which is used as it is,
// such an assignment is an InputError saying so.
bool changesMultimesh(const std::vector<std::string>& sets, const std::string& meshFile = "");

}  // namespace ib::cli
