// `inbetween export`: a scene's animation as a glTF 2.0 file (.glb or .gltf + .bin).
#pragma once

#include <string>
#include <vector>

namespace ib {

// args: the words after `export`. Returns the exit code; bad input throws InputError.
int runExport(const std::vector<std::string>& args);

}  // namespace ib
