// `inbetween render SCENE -o DIR [...]`: the scene's timeline rendered headless to numbered PNG
// frames and a contact sheet.
#pragma once

#include <string>
#include <vector>

namespace ib {

int runRender(const std::vector<std::string>& args);

}  // namespace ib
