// The operations of `inbetween edit SCENE --apply OPS.json` (docs/editor.md): a JSON array of
// objects, each {"op": NAME, ...}, read into the scene document's typed edits (scene_edits.h), the
// same edits the editor window makes. Reading checks only the operations' own form; whether an
// edit applies (the key exists, the name is free) is the document's to say.
#pragma once

#include "scene/scene_edits.h"

#include <string>
#include <vector>

namespace ib {

struct EditOp {
  int index = 0;           // its place in the array, from 0
  std::string op;          // its "op"
  edit::SceneEdit edit;    // what it does (for "set": unused, see assignment)
  std::string assignment;  // "set": NAME=VALUE for SceneDocument::setFromText; empty otherwise
  // add_feature, move_feature: the point is snapped onto the key's outline before it applies.
  bool snapsToOutline = false;
};

// Reads the operations of `text` (the file `file`'s contents). InputError naming the file, the
// operation's index and op, and the field: not an array, an unknown op (did you mean), a field
// missing or of the wrong type, a point that is not [x, y] of finite numbers, a radius or kappa
// that is not a positive number.
std::vector<EditOp> readEditOps(const std::string& text, const std::string& file);

// The names of the operations readEditOps knows, for messages and docs.
const std::vector<std::string>& editOpNames();

}  // namespace ib
