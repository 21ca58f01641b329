// Every key's drawing, read for a front end that draws them, with a bad one named as the build
// names it: `walk.json: key "arch": drawing arch.png: cannot open (No such file or directory)`.
#pragma once

#include "core/png_image.h"

#include <vector>

namespace ib {

struct Scene;       // scene/scene.h
class TraceCache;   // meshing/trace_cache.h

// [key]: the drawing as 8-bit RGBA, the artwork every front end draws. A drawing traced by colour
// (no alpha, or tracing.background set) comes with its paper made transparent and its outline's
// antialiasing un-blended from the paper (meshing/paper.h: paperToAlpha), enclosed paper kept
// opaque unless marked as a hole, so the artwork has the traced shape's holes. Throws
// InputError naming the scene file, the key and the drawing when one cannot be read or a hole
// point is misplaced. With `traces`, a drawing it holds (the build before read it) is not read again.
std::vector<RgbaImage> readKeyDrawings(const Scene& scene, TraceCache* traces = nullptr);

}  // namespace ib
