// A glTF document to bytes and files (internal to the exporter): binary .glb (the JSON and buffer
// 0 in one file) or .gltf JSON with buffer 0 beside it as NAME.bin; images are always in the
// buffer. tinygltf serializes the JSON; the buffers are added here, since tinygltf cannot write a
// buffer of a given length without data (the meshopt fallback buffer).
#pragma once

#include "export/gltf_document.h"

#include <string>

namespace ib::gltf {

enum class Container { kGlb, kGltf };

// The files' total size in bytes, as writeDocument would write them.
size_t documentBytes(const GltfDocument& doc, Container container, const std::string& binName = "scene.bin");

// Writes `path` (.glb, or .gltf with its .bin beside it), each file atomically; when the .gltf
// cannot be written after its .bin, a .bin that did not exist before is removed again. Returns
// the bytes written (documentBytes of the same). Throws InputError naming the path when a file
// cannot be written.
size_t writeDocument(const GltfDocument& doc, const std::string& path);

// The container a path's extension names (.glb or .gltf, any case); InputError naming the path
// and the `field` otherwise.
Container containerOf(const std::string& path, const std::string& field);

}  // namespace ib::gltf
