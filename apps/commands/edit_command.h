// `inbetween edit SCENE --apply OPS.json [-o OUT.json]` (operations on a scene, as the editor
// makes them: docs/editor.md) and `inbetween new SCENE.json A.png B.png ...` (a scene started from
// drawings).
#pragma once

#include <string>
#include <vector>

namespace ib {

int runEdit(const std::vector<std::string>& args);
int runNew(const std::vector<std::string>& args);

}  // namespace ib
