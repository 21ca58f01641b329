// Atomic output: write to a temporary file beside the target, then rename over it, so a failure
// never leaves a half-written file over a good one.
#pragma once

#include <string>

namespace ib {

// Writes bytes to path atomically. Throws InputError naming the path when it cannot be written.
void writeFileAtomically(const std::string& path, const std::string& bytes);

// Reads a whole file. Throws InputError naming the path when it cannot be read or is a folder.
std::string readFile(const std::string& path);

}  // namespace ib
