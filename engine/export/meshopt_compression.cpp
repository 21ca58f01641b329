#include "export/meshopt_compression.h"

#include <meshoptimizer.h>

#include <cstring>
#include <stdexcept>

namespace ib::gltf {

namespace {

std::vector<unsigned char> encodeAttributes(const unsigned char* data, const ViewCodec& codec) {
  std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(codec.count, codec.stride));
  out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, codec.count, codec.stride));
  return out;
}

std::vector<unsigned char> encodeTriangles(const unsigned char* data, const ViewCodec& codec, size_t vertexCount) {
  std::vector<unsigned int> indices(codec.count);
  for (int i = 0; i < codec.count; ++i) {
    if (codec.stride == 2) {
      uint16_t v;
      std::memcpy(&v, data + 2 * i, 2);
      indices[i] = v;
    } else {
      std::memcpy(&indices[i], data + 4 * i, 4);
    }
  }
  std::vector<unsigned char> out(meshopt_encodeIndexBufferBound(indices.size(), vertexCount));
  out.resize(meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), indices.size()));
  return out;
}

}  // namespace

void compressWithMeshopt(GltfDocument& doc) {
  if (doc.fallbackBytes) throw std::logic_error("compressWithMeshopt: already compressed");
  meshopt_encodeIndexVersion(1);  // the version EXT_meshopt_compression's TRIANGLES mode names
  size_t vertexCount = 0;
  for (const tinygltf::Accessor& a : doc.model.accessors)
    if (doc.views[a.bufferView].kind == ViewCodec::Kind::kAttributes) vertexCount = std::max(vertexCount, a.count);
  std::vector<unsigned char> packed;
  for (size_t i = 0; i < doc.model.bufferViews.size(); ++i) {
    tinygltf::BufferView& view = doc.model.bufferViews[i];
    const ViewCodec& codec = doc.views[i];
    const unsigned char* data = doc.bin.data() + view.byteOffset;
    while (packed.size() % 4) packed.push_back(0);
    if (codec.kind == ViewCodec::Kind::kNone) {
      const size_t offset = packed.size();
      packed.insert(packed.end(), data, data + view.byteLength);
      view.byteOffset = offset;
      continue;
    }
    const std::vector<unsigned char> encoded =
        codec.kind == ViewCodec::Kind::kAttributes ? encodeAttributes(data, codec) : encodeTriangles(data, codec, vertexCount);
    tinygltf::Value::Object ext;
    ext["buffer"] = tinygltf::Value(0);
    ext["byteOffset"] = tinygltf::Value(static_cast<int>(packed.size()));
    ext["byteLength"] = tinygltf::Value(static_cast<int>(encoded.size()));
    ext["byteStride"] = tinygltf::Value(codec.stride);
    ext["count"] = tinygltf::Value(codec.count);
    ext["mode"] = tinygltf::Value(std::string(codec.kind == ViewCodec::Kind::kAttributes ? "ATTRIBUTES" : "TRIANGLES"));
    view.extensions["EXT_meshopt_compression"] = tinygltf::Value(ext);
    view.buffer = 1;  // its uncompressed layout, in the fallback buffer at its old offset
    packed.insert(packed.end(), encoded.begin(), encoded.end());
  }
  doc.fallbackBytes = doc.bin.size();
  doc.bin = std::move(packed);
  doc.model.extensionsUsed.push_back("EXT_meshopt_compression");
  doc.model.extensionsRequired.push_back("EXT_meshopt_compression");
}

}  // namespace ib::gltf
