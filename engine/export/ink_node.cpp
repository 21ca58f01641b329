#include "export/ink_node.h"

#include "export/ink_strips.h"

namespace ib::gltf {

int addInkNode(GltfDocument& doc, Writer& writer, const DocumentInput& in) {
  const BakedAnimation& baked = *in.baked;
  const render::CutInks& inks = in.mesh->inks;
  if (inks.sides.empty() || baked.closure.size() != baked.frames.size()) return -1;
  const InkStrips strips = inkStripsOf(inks, in.mesh->triangles);
  const int n = strips.vertexCount();
  std::vector<Eigen::MatrixX2d> positions;
  std::vector<std::vector<float>> colours;
  for (size_t f = 0; f < baked.frames.size(); ++f) {
    positions.push_back(inkStripPositions(strips, inks, baked.positions[f]));
    colours.push_back(inkStripColours(strips, inks, baked.closure[f], baked.weights[f]));
  }
  const PositionCodec codec(in.canvas, in.pixelsPerUnit, in.codec->quantized(), positions.front(), positions);

  doc.model.materials.push_back(unlitMaterial("ink"));

  tinygltf::Primitive primitive;
  primitive.indices = indicesAccessor(writer, strips.triangles, n);
  primitive.attributes["POSITION"] = writer.accessor(codec.base(), 3, n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                     TINYGLTF_TYPE_VEC3, false, kArrayBuffer, true);
  primitive.attributes["COLOR_0"] = writer.accessor(colours.front(), 4, n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                    TINYGLTF_TYPE_VEC4, false, kArrayBuffer, false);
  primitive.material = static_cast<int>(doc.model.materials.size()) - 1;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  for (size_t t = 1; t < in.kept.size(); ++t) {
    const int f = in.kept[t];
    const int position = codec.quantized()
                             ? writer.accessor(codec.shortDeltas(positions[f]), 3, n, TINYGLTF_COMPONENT_TYPE_SHORT,
                                               TINYGLTF_TYPE_VEC3, true, kArrayBuffer, true, 8)
                             : writer.accessor(codec.floatDeltas(positions[f]), 3, n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                               TINYGLTF_TYPE_VEC3, false, kArrayBuffer, true);
    std::vector<float> colour = colours[f];
    for (size_t i = 0; i < colour.size(); ++i) colour[i] -= colours.front()[i];
    const int delta = writer.accessor(colour, 4, n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, false, kArrayBuffer, false);
    primitive.targets.push_back({{"POSITION", position}, {"COLOR_0", delta}});
  }
  tinygltf::Mesh mesh;
  mesh.name = in.name + " ink";
  mesh.primitives.push_back(primitive);
  mesh.weights.assign(in.kept.size() - 1, 0.0);
  doc.model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = in.name + " ink";
  node.mesh = static_cast<int>(doc.model.meshes.size()) - 1;
  // One drawing pixel in front of the shape (+Z, towards the viewer): clients sort transparent
  // objects by their distance, so the ink draws after the layers it lies on, with no depth fighting.
  node.translation = {codec.translation()[0], codec.translation()[1], codec.translation()[2] + 1.0 / in.pixelsPerUnit};
  if (codec.quantized()) node.scale = {codec.scale(), codec.scale(), codec.scale()};
  doc.model.nodes.push_back(node);
  return static_cast<int>(doc.model.nodes.size()) - 1;
}

}  // namespace ib::gltf
