// What the command-line tests (test_cli_*.cpp) share: `inbetween` run with explicit arguments,
// its stdout read as JSON lines, and the example scenes (testkit/example_scenes.h) written once
// per test process into a scratch folder of its own, so every test case runs alone, in any
// order, beside the others.
#pragma once

#include "testkit/command_run.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace test {

// Runs `inbetween ARGS...` (INBETWEEN_CLI); `prefix` is put before it (e.g. "env VAR=VALUE").
CommandRun inbetween(const std::vector<std::string>& args, const std::string& prefix = "");

// Every line of `out` parsed as JSON (an empty last line skipped); fails the test case on a line
// that is not JSON.
std::vector<nlohmann::json> jsonLines(const std::string& out);

// FOLDER/NAME/scene.json of the good or Comesh example scene NAME (goodScenes(), comeshScenes()),
// written on first use.
std::string exampleScene(const std::string& name);

// FOLDER/bad/FILE: the bad scenes (writeBadScenes), written on first use with square-arch-notch,
// whose drawings they use.
std::string badScene(const std::string& file);

// FOLDER/RELATIVE, for a command's output; not created. The folder is this process's alone and
// removed when the process ends.
std::string scratchPath(const std::string& relative);

// Whether `path` exists (a file or a folder).
bool exists(const std::string& path);

}  // namespace test
