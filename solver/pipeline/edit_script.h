// `inbetween edit SCENE --apply OPS.json`: a script of operations (scene/edit_ops.h) applied to a
// scene document as the editor window applies its edits. A feature's point is snapped onto its
// key's traced outline first, as a click in the window is; at the end the document must be a
// scene that loads and whose every key's shape builds (features on the outline, cuts inside the
// shape, meshing/key_shape.h). CPU only.
#pragma once

#include "scene/edit_ops.h"
#include "scene/scene_document.h"

#include <string>
#include <vector>

namespace ib {

struct EditScriptOptions {
  // px: a feature placed farther than this from its key's traced outline is an error; closer, it
  // moves onto the nearest outline point. Default 8, as the mesher's snap (KeyShapeOptions).
  double snapDistance = 8;
};

// Applies `ops` (read from `opsFile`, named in messages) to `doc` in order. InputError naming the
// operation (its index and op) and what is wrong, or "after the operations" and the scene's own
// message (file, key, field) for the result; `doc` may then hold some of the edits: callers keep
// a copy to write nothing. The document must load before the first operation.
void applyEditScript(SceneDocument& doc, const std::vector<EditOp>& ops, const std::string& opsFile,
                     const EditScriptOptions& options = {});

}  // namespace ib
