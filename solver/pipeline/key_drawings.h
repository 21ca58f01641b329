// Every key's drawing, read for a front end that draws them, with a bad one named as the build
// names it: `walk.json: key "arch": drawing arch.png: cannot open (No such file or directory)`.
#pragma once

#include "core/png_image.h"

#include <vector>

namespace ib {

struct Scene;  // scene/scene.h

// [key]: the drawing as 8-bit RGBA. Throws InputError naming the scene file, the key and the
// drawing when one cannot be read.
std::vector<RgbaImage> readKeyDrawings(const Scene& scene);

}  // namespace ib
