// `inbetween parameters`: the parameter table (scene/parameters.h), as text or as the Markdown
// table of docs/parameters.md.
#pragma once

#include <string>
#include <vector>

namespace ib {

int runParameters(const std::vector<std::string>& args);

}  // namespace ib
