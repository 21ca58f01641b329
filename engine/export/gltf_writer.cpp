#include "export/gltf_writer.h"

namespace ib::gltf {

tinygltf::Material unlitMaterial(const std::string& name) {
  tinygltf::Material material;
  material.name = name;
  material.pbrMetallicRoughness.baseColorFactor = {1, 1, 1, 1};
  material.pbrMetallicRoughness.metallicFactor = 0;
  material.pbrMetallicRoughness.roughnessFactor = 1;
  material.alphaMode = "BLEND";
  material.doubleSided = true;
  material.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
  return material;
}

int indicesAccessor(Writer& writer, const std::vector<Triangle>& triangles, int vertexCount) {
  const int count = 3 * static_cast<int>(triangles.size());
  if (vertexCount <= 65535) {
    std::vector<uint16_t> indices;
    for (const Triangle& t : triangles)
      for (int c = 0; c < 3; ++c) indices.push_back(static_cast<uint16_t>(t[c]));
    return writer.accessor(indices, 1, count, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, false,
                           kElementArrayBuffer, false);
  }
  std::vector<uint32_t> indices;
  for (const Triangle& t : triangles)
    for (int c = 0; c < 3; ++c) indices.push_back(static_cast<uint32_t>(t[c]));
  return writer.accessor(indices, 1, count, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, false,
                         kElementArrayBuffer, false);
}

}  // namespace ib::gltf
