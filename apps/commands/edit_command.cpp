#include "commands/edit_command.h"

#include "cli.h"
#include "commands/play_command.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "pipeline/edit_script.h"
#include "scene/scene_document.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ib {

namespace {

namespace fs = std::filesystem;

constexpr const char* kEditUsage =
    "usage: inbetween edit SCENE [window options]\n"
    "       inbetween edit SCENE --apply OPS.json [-o OUT.json] [--snap PX]\n"
    "\n"
    "Opens the editor: the keys side by side above the animation, each with its traced outline.\n"
    "Place features by clicking on the outlines (the arcs between them take the same colour in every\n"
    "key), draw cuts, interior features and painted stiffness; the animation rebuilds after every\n"
    "edit. Ctrl+Z / Ctrl+Shift+Z undo and redo, Ctrl+S saves (docs/editor.md). The window takes\n"
    "`inbetween play`'s options (--size, --validation, --frames N --screenshot PATH, ...).\n"
    "\n"
    "With --apply, applies the operations of OPS.json (a JSON array, docs/editor.md) to SCENE and\n"
    "writes it, in place or to OUT.json, keeping the file's layout, without a window. A feature's\n"
    "point snaps onto its key's traced outline within --snap px. A bad operation, or a scene that\n"
    "would not load or mesh afterwards (a feature in one key only, a cut leaving the shape), is an\n"
    "error naming the operation and field: nothing is written.\n"
    "\n"
    "  --apply OPS.json   the operations\n"
    "  -o, --output OUT   write the scene here (drawing paths rewritten to resolve from its folder)\n"
    "  --snap PX          how far from the outline a feature may be placed (default 8)\n";

constexpr const char* kNewUsage =
    "usage: inbetween new SCENE.json A.png B.png [...]\n"
    "\n"
    "Writes a scene with one key per drawing, in that order, each named after its file without the\n"
    "extension, and a timeline that holds each key for a second and loops; no features or cuts yet\n"
    "(add them in the editor, which opens on the new scene, or with `inbetween edit SCENE --apply\n"
    "OPS.json`). SCENE.json must not exist.\n"
    "\n"
    "  --fps N       the timeline's frames per second (default 24)\n"
    "  --no-window   only write the scene\n";

// A number as the scene files write it: whole numbers without a fraction.
nlohmann::ordered_json number(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e15) return static_cast<long long>(value);
  return value;
}

// The scene's text for `out`: as the document has it when out is in the scene's folder, else with
// every relative drawing path rewritten to resolve from out's folder.
std::string textFor(const SceneDocument& doc, const std::string& out) {
  const fs::path from = fs::absolute(doc.path()).parent_path(), to = fs::absolute(out).parent_path();
  if (fs::weakly_canonical(from) == fs::weakly_canonical(to)) return doc.text();
  nlohmann::ordered_json json = nlohmann::ordered_json::parse(doc.text());
  for (auto& key : json["keys"])
    if (key.contains("drawing") && key["drawing"].is_string() && !fs::path(key["drawing"].get<std::string>()).is_absolute())
      key["drawing"] = fs::relative(from / key["drawing"].get<std::string>(), to).generic_string();
  return json.dump(2) + "\n";
}

// The editor's window with edit's arguments; without the engine there is none.
int openEditor(const std::vector<std::string>& args) {
#ifdef INBETWEEN_WITH_ENGINE
  return runPlayerWindow(args, true);
#else
  (void)args;
  throw InputError("edit: this inbetween was built without the engine (INBETWEEN_ENGINE=OFF), which draws the editor's "
                   "window: edit with --apply, or build with the engine");
#endif
}

}  // namespace

int runEdit(const std::vector<std::string>& args) {
  if (cli::printHelpIfAsked(args, kEditUsage)) return 0;
  if (std::none_of(args.begin(), args.end(), [](const std::string& a) { return a.rfind("--apply", 0) == 0; }))
    return openEditor(args);
  const cli::Arguments arguments("edit", cli::expandShortOutput(args), {"apply", "output", "snap"}, {});
  if (arguments.positional().size() != 1) throw InputError("edit: expected one SCENE (see `inbetween edit --help`)");
  const std::string scene = arguments.positional()[0], opsFile = arguments.value("apply", "");
  EditScriptOptions options;
  if (arguments.has("snap")) options.snapDistance = cli::positiveNumber(arguments.value("snap", ""), "--snap", 1000, "a distance in drawing pixels");
  const std::vector<EditOp> ops = readEditOps(readFile(opsFile), opsFile);
  SceneDocument doc = SceneDocument::load(scene);
  applyEditScript(doc, ops, opsFile, options);
  const std::string out = arguments.value("output", scene);
  writeFileAtomically(out, textFor(doc, out));
  std::printf("%s: applied %zu operation%s, wrote %s\n", scene.c_str(), ops.size(), ops.size() == 1 ? "" : "s", out.c_str());
  return 0;
}

int runNew(const std::vector<std::string>& args) {
  if (cli::printHelpIfAsked(args, kNewUsage)) return 0;
  const cli::Arguments arguments("new", args, {"fps"}, {"no-window"});
  const std::vector<std::string>& words = arguments.positional();
  if (words.size() < 3) throw InputError("new: expected SCENE.json and at least two drawings (see `inbetween new --help`)");
  const std::string scene = words[0];
  if (fs::exists(scene)) throw InputError("new: " + scene + " exists already: choose another name, or edit it (`inbetween edit`)");
  const double fps = arguments.has("fps") ? cli::positiveNumber(arguments.value("fps", ""), "--fps", 1000, "a frame rate") : 24;
  const fs::path folder = fs::absolute(scene).parent_path();
  nlohmann::ordered_json json{{"version", 1}, {"keys", nlohmann::ordered_json::array()}};
  nlohmann::ordered_json marks = nlohmann::ordered_json::array();
  std::vector<std::string> names;
  for (size_t i = 1; i < words.size(); ++i) {
    const fs::path drawing = words[i];
    if (!fs::is_regular_file(drawing)) throw InputError("new: drawing " + words[i] + " does not exist: give the PNG files of the keys");
    const std::string name = drawing.stem().string();
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw InputError("new: two drawings are named " + inQuotes(name) + ": keys are named after their files; rename one");
    names.push_back(name);
    json["keys"].push_back({{"name", name}, {"drawing", fs::relative(fs::absolute(drawing), folder).generic_string()}});
    marks.push_back({{"time", number(static_cast<double>(i - 1))}, {"key", name}});
  }
  marks.push_back({{"time", number(static_cast<double>(names.size()))}, {"key", names.front()}});
  json["timeline"] = {{"fps", number(fps)}, {"loop", true}, {"marks", marks}};
  const std::string text = json.dump(2) + "\n";
  SceneDocument doc = SceneDocument::fromText(text, scene);  // the drawings must load as a scene
  if (doc.problem()) throw InputError(*doc.problem());
  writeFileAtomically(scene, text);
  std::printf("wrote %s: %zu keys (%s", scene.c_str(), names.size(), names.front().c_str());
  for (size_t i = 1; i < names.size(); ++i) std::printf(", %s", names[i].c_str());
  std::printf("), a %zu s loop at %g fps\n", names.size(), fps);
  std::fflush(stdout);
  if (arguments.flag("no-window")) return 0;
#ifdef INBETWEEN_WITH_ENGINE
  return runPlayerWindow({scene}, true);
#else
  std::printf("no editor window: this inbetween was built without the engine (INBETWEEN_ENGINE=OFF)\n");
  return 0;
#endif
}

}  // namespace ib
