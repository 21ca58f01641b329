// The glTF node that draws opened cuts' outline ink (internal to the exporter): one mesh of ink
// strips (export/ink_strips.h) with the same morph targets as the shape's mesh, so one weights
// animation moves both, and the ink's alpha per vertex carried as COLOR_0 morph-target deltas, so
// it fades in clients that morph vertex colours (three.js core) without KHR_animation_pointer.
// docs/export.md "Ink on opened cuts".
#pragma once

#include "export/gltf_writer.h"

namespace ib::gltf {

// Adds the ink's material, mesh and node when the render mesh's inks have sides and the frames
// carry their closure; returns the node's index, or -1 when there is no ink to draw.
int addInkNode(GltfDocument& doc, Writer& writer, const DocumentInput& in);

}  // namespace ib::gltf
