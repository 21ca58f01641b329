// `inbetween mesh SCENE [-o OUT] [--json] [--no-pictures]`: builds the scene's multimesh, writes
// it and one SVG per key, and prints what was built.
#pragma once

#include <string>
#include <vector>

namespace ib {

int runMesh(const std::vector<std::string>& args);

}  // namespace ib
