// An SVG picture of one key of a multimesh over its drawing, so an author sees what was built:
// triangles in thin blue, cohesive edges in red, features as labelled dots. The drawing is embedded
// (base64 PNG), so the file stands alone. Coordinates are drawing pixels.
#pragma once

#include "meshing/key_shape.h"
#include "multimesh/multimesh.h"

#include <string>

namespace ib {

// drawingPng: the drawing's PNG bytes; width, height: its size in pixels.
std::string meshSvg(const Multimesh& mesh, int key, const KeyShape& shape, const std::string& drawingPng, int width,
                    int height);

}  // namespace ib
