// Appending bufferViews and accessors to a glTF document (internal to the exporter: it shows
// tinygltf). docs/export.md.
#pragma once

#include "export/gltf_document.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace ib::gltf {

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// Appends bufferViews (4-byte aligned, one per accessor) and accessors to a document.
class Writer {
 public:
  explicit Writer(GltfDocument& doc) : doc_(doc) {}

  int view(const void* data, size_t bytes, ViewCodec codec, int target, int byteStride = 0) {
    while (doc_.bin.size() % 4) doc_.bin.push_back(0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = doc_.bin.size();
    v.byteLength = bytes;
    v.byteStride = static_cast<size_t>(byteStride);
    v.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    doc_.bin.insert(doc_.bin.end(), p, p + bytes);
    doc_.model.bufferViews.push_back(v);
    doc_.views.push_back(codec);
    return static_cast<int>(doc_.model.bufferViews.size()) - 1;
  }

  // An accessor of `count` elements of `components` each over its own bufferView; min/max from
  // the stored values, as the validator compares them.
  template <typename T>
  int accessor(const std::vector<T>& values, int components, int count, int componentType, int type, bool normalized,
               int target, bool minMax, int stride = 0) {
    const int elementBytes = stride > 0 ? stride : components * static_cast<int>(sizeof(T));
    const int perElement = elementBytes / static_cast<int>(sizeof(T));
    ViewCodec codec;
    codec.kind = target == kElementArrayBuffer ? ViewCodec::Kind::kTriangles : ViewCodec::Kind::kAttributes;
    codec.stride = elementBytes;
    codec.count = count;
    if (codec.kind == ViewCodec::Kind::kAttributes && elementBytes % 4) codec.kind = ViewCodec::Kind::kNone;
    tinygltf::Accessor a;
    a.bufferView = view(values.data(), values.size() * sizeof(T), codec, target, stride);
    a.byteOffset = 0;
    a.componentType = componentType;
    a.count = static_cast<size_t>(count);
    a.type = type;
    a.normalized = normalized;
    if (minMax) {
      a.minValues.assign(components, std::numeric_limits<double>::infinity());
      a.maxValues.assign(components, -std::numeric_limits<double>::infinity());
      for (int e = 0; e < count; ++e)
        for (int c = 0; c < components; ++c) {
          const double v = static_cast<double>(values[static_cast<size_t>(e) * perElement + c]);
          a.minValues[c] = std::min(a.minValues[c], v);
          a.maxValues[c] = std::max(a.maxValues[c], v);
        }
    }
    doc_.model.accessors.push_back(a);
    return static_cast<int>(doc_.model.accessors.size()) - 1;
  }

 private:
  GltfDocument& doc_;
};

// An unlit (KHR_materials_unlit), alpha-blended, double-sided material: white base colour, not
// metallic, fully rough (what a client without the extension falls back on).
tinygltf::Material unlitMaterial(const std::string& name);

// A triangle list's indices: 16-bit when `vertexCount` allows, else 32-bit.
int indicesAccessor(Writer& writer, const std::vector<Triangle>& triangles, int vertexCount);

}  // namespace ib::gltf
