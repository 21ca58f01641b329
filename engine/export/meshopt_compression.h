// EXT_meshopt_compression (internal to the exporter): every vertex, index and animation
// bufferView re-encoded with meshoptimizer's codecs (Debian's libmeshoptimizer-dev). The encoded
// bytes become buffer 0; the bufferViews keep their layout in buffer 1, a fallback buffer without
// data, so a client needs the extension (it is listed as required). Images stay as they are.
#pragma once

#include "export/gltf_document.h"

namespace ib::gltf {

// Compresses `doc` in place. Decoders: three.js's GLTFLoader with MeshoptDecoder, Babylon.js,
// gltfpack and glTF-Transform read it; docs/export.md lists them.
void compressWithMeshopt(GltfDocument& doc);

}  // namespace ib::gltf
