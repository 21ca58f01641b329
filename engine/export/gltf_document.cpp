#include "export/gltf_document.h"

#include "export/artwork_bleed.h"
#include "export/gltf_writer.h"
#include "export/ink_node.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace ib::gltf {

namespace {

// Text for the JSON: glTF strings are UTF-8, and a name may not be (a folder name on Linux is any
// bytes; found by the fuzz target), which tinygltf's JSON writer throws on. Every invalid byte
// becomes U+FFFD, through nlohmann's own UTF-8 check.
std::string validUtf8(const std::string& text) {
  const std::string quoted = nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return nlohmann::json::parse(quoted).get<std::string>();
}

DocumentInput withValidNames(const DocumentInput& input) {
  DocumentInput in = input;
  in.name = validUtf8(in.name);
  for (std::string& key : in.keyNames) key = validUtf8(key);
  return in;
}

int uvAccessor(Writer& writer, const Eigen::MatrixX2f& uv, bool quantized) {
  const int n = static_cast<int>(uv.rows());
  if (!quantized) {
    std::vector<float> values(2 * static_cast<size_t>(n));
    for (int v = 0; v < n; ++v)
      for (int c = 0; c < 2; ++c) values[2 * v + c] = std::clamp(uv(v, c), 0.0f, 1.0f);
    return writer.accessor(values, 2, n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, false, kArrayBuffer, false);
  }
  std::vector<uint16_t> values(2 * static_cast<size_t>(n));
  for (int v = 0; v < n; ++v)
    for (int c = 0; c < 2; ++c)
      values[2 * v + c] = static_cast<uint16_t>(std::lround(std::clamp(double(uv(v, c)), 0.0, 1.0) * 65535.0));
  return writer.accessor(values, 2, n, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC2, true, kArrayBuffer,
                         false);
}

// Every key that has weight somewhere in the baked frames, in key order: the layers.
std::vector<int> drawnKeys(const BakedAnimation& baked) {
  std::vector<int> keys;
  const Eigen::Index m = baked.weights.front().size();
  for (Eigen::Index k = 0; k < m; ++k)
    for (const Eigen::VectorXd& w : baked.weights)
      if (w[k] > 0) {
        keys.push_back(static_cast<int>(k));
        break;
      }
  if (keys.empty()) keys.push_back(0);
  return keys;
}

void addTextures(GltfDocument& doc, Writer& writer, const DocumentInput& in, const std::vector<int>& layers) {
  tinygltf::Sampler sampler;
  sampler.magFilter = in.nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST : TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = in.nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST : TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  doc.model.samplers.push_back(sampler);
  for (int key : layers) {
    const std::string png = encodePng(bleedColour(in.mesh->artwork[key]));
    tinygltf::Image image;
    image.name = in.keyNames[key];
    image.mimeType = "image/png";
    image.bufferView = writer.view(png.data(), png.size(), {}, 0);
    doc.model.images.push_back(image);
    tinygltf::Texture texture;
    texture.sampler = 0;
    texture.source = static_cast<int>(doc.model.images.size()) - 1;
    doc.model.textures.push_back(texture);
  }
}

void addMaterials(GltfDocument& doc, const DocumentInput& in, const std::vector<int>& layers,
                  const std::vector<double>& firstAlphas) {
  for (size_t l = 0; l < layers.size(); ++l) {
    tinygltf::Material material = unlitMaterial(in.keyNames[layers[l]]);
    material.pbrMetallicRoughness.baseColorTexture.index = static_cast<int>(l);
    material.pbrMetallicRoughness.baseColorFactor = {1, 1, 1, firstAlphas[layers[l]]};
    doc.model.materials.push_back(material);
  }
}

// The clip's keyframe times for frames `frames` (indices into the baked frames), plus the loop's
// closing keyframe a frame after the last, which repeats the first.
std::vector<float> keyframeTimes(const BakedAnimation& baked, const std::vector<int>& frames) {
  std::vector<float> times;
  for (int f : frames) times.push_back(static_cast<float>(baked.times[f]));
  if (baked.loops) times.push_back(static_cast<float>(baked.times.back() + 1.0 / baked.fps));
  return times;
}

}  // namespace

std::vector<double> layerAlphas(const Eigen::VectorXd& w) {
  std::vector<double> alphas(static_cast<size_t>(w.size()), 0.0);
  double below = 0;
  for (Eigen::Index k = 0; k < w.size(); ++k) {
    const double wk = std::max(0.0, w[k]);
    below += wk;
    alphas[k] = below > 0 ? wk / below : 0.0;
  }
  return alphas;
}

GltfDocument buildDocument(const DocumentInput& input) {
  const DocumentInput in = withValidNames(input);
  const BakedAnimation& baked = *in.baked;
  const render::RenderMesh& mesh = *in.mesh;
  const PositionCodec& codec = *in.codec;
  if (baked.frames.empty() || in.kept.empty() || in.kept.front() != 0)
    throw std::invalid_argument("buildDocument: needs baked frames, with the first one kept as the base");
  GltfDocument doc;
  tinygltf::Model& model = doc.model;
  Writer writer(doc);
  const int n = mesh.vertexCount;
  const bool quantized = codec.quantized();

  model.asset.version = "2.0";
  model.asset.generator = "inbetween";
  tinygltf::Value::Object info;
  info["canvas"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(in.canvas[0]), tinygltf::Value(in.canvas[1])});
  info["pixelsPerUnit"] = tinygltf::Value(in.pixelsPerUnit);
  info["fps"] = tinygltf::Value(baked.fps);
  info["frames"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(baked.frames.front()), tinygltf::Value(baked.frames.back())});
  info["shapeSize"] = tinygltf::Value(baked.shapeSize);
  // The animation's bounds over every baked frame, drawing px (x0, y0, x1, y1; y down): where it
  // reaches past the canvas, a client placing the sprite by its canvas learns how far.
  const render::ViewBox bounds = render::boundsOf(baked.positions);
  info["bounds"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(bounds.x0), tinygltf::Value(bounds.y0), tinygltf::Value(bounds.x1),
                                                          tinygltf::Value(bounds.y1)});
  tinygltf::Value::Object extras;
  extras["inbetween"] = tinygltf::Value(info);
  model.asset.extras = tinygltf::Value(extras);

  const int indices = indicesAccessor(writer, mesh.triangles, n);
  const int base = writer.accessor(codec.base(), 3, n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, false,
                                   kArrayBuffer, true);
  std::vector<int> targets;
  std::vector<std::string> targetNames;
  for (size_t t = 1; t < in.kept.size(); ++t) {
    const Eigen::MatrixX2d& frame = baked.positions[in.kept[t]];
    targets.push_back(quantized ? writer.accessor(codec.shortDeltas(frame), 3, n, TINYGLTF_COMPONENT_TYPE_SHORT,
                                                  TINYGLTF_TYPE_VEC3, true, kArrayBuffer, true, 8)
                                : writer.accessor(codec.floatDeltas(frame), 3, n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                  TINYGLTF_TYPE_VEC3, false, kArrayBuffer, true));
    targetNames.push_back("frame " + std::to_string(baked.frames[in.kept[t]]));
  }

  const std::vector<int> layers = drawnKeys(baked);
  addTextures(doc, writer, in, layers);
  addMaterials(doc, in, layers, layerAlphas(baked.weights.front()));

  tinygltf::Mesh gmesh;
  gmesh.name = in.name;
  for (size_t l = 0; l < layers.size(); ++l) {
    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = base;
    primitive.attributes["TEXCOORD_0"] = uvAccessor(writer, mesh.keyUV[layers[l]], quantized);
    primitive.indices = indices;
    primitive.material = static_cast<int>(l);
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    for (int target : targets) primitive.targets.push_back({{"POSITION", target}});
    gmesh.primitives.push_back(primitive);
  }
  gmesh.weights.assign(targets.size(), 0.0);
  if (!targetNames.empty()) {
    tinygltf::Value::Array names;
    for (const std::string& s : targetNames) names.emplace_back(s);
    tinygltf::Value::Object meshExtras;
    meshExtras["targetNames"] = tinygltf::Value(names);
    gmesh.extras = tinygltf::Value(meshExtras);
  }
  model.meshes.push_back(gmesh);

  tinygltf::Node node;
  node.name = in.name;
  node.mesh = 0;
  if (quantized) {
    node.translation = {codec.translation()[0], codec.translation()[1], codec.translation()[2]};
    node.scale = {codec.scale(), codec.scale(), codec.scale()};
  }
  model.nodes.push_back(node);
  const int inkNode = addInkNode(doc, writer, in);
  tinygltf::Scene scene;
  scene.name = in.name;
  scene.nodes = {0};
  if (inkNode >= 0) scene.nodes.push_back(inkNode);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  // The animation: morph weights at the kept frames' times (each a unit vector, or zero at the
  // base), and each layer's alpha factor at every frame's time.
  tinygltf::Animation animation;
  animation.name = in.name;
  const bool animated = baked.frames.size() > 1;
  if (animated && !targets.empty()) {
    const std::vector<float> times = keyframeTimes(baked, in.kept);
    const int keyframes = static_cast<int>(times.size());
    std::vector<float> weights(static_cast<size_t>(keyframes) * targets.size(), 0.0f);
    for (size_t t = 1; t < in.kept.size(); ++t) weights[t * targets.size() + (t - 1)] = 1.0f;
    tinygltf::AnimationSampler sampler;
    sampler.input = writer.accessor(times, 1, keyframes, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, false, 0, true);
    sampler.output = writer.accessor(weights, 1, static_cast<int>(weights.size()), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                     TINYGLTF_TYPE_SCALAR, false, 0, false);
    sampler.interpolation = "LINEAR";
    animation.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    animation.channels.push_back(channel);
    if (inkNode >= 0) {
      channel.target_node = inkNode;  // the ink's strips move with the same targets and weights
      animation.channels.push_back(channel);
    }
  }
  if (animated && layers.size() > 1) {
    std::vector<int> all(baked.frames.size());
    for (size_t f = 0; f < all.size(); ++f) all[f] = static_cast<int>(f);
    const std::vector<float> times = keyframeTimes(baked, all);
    const int input = writer.accessor(times, 1, static_cast<int>(times.size()), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                      TINYGLTF_TYPE_SCALAR, false, 0, true);
    std::vector<std::vector<double>> alphas;
    for (const Eigen::VectorXd& w : baked.weights) alphas.push_back(layerAlphas(w));
    if (baked.loops) alphas.push_back(alphas.front());
    for (size_t l = 0; l < layers.size(); ++l) {
      std::vector<float> factors;
      for (const std::vector<double>& a : alphas) factors.insert(factors.end(), {1.0f, 1.0f, 1.0f, static_cast<float>(a[layers[l]])});
      tinygltf::AnimationSampler sampler;
      sampler.input = input;
      sampler.output = writer.accessor(factors, 4, static_cast<int>(alphas.size()), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                       TINYGLTF_TYPE_VEC4, false, 0, false);
      sampler.interpolation = "LINEAR";
      animation.samplers.push_back(sampler);
      tinygltf::AnimationChannel channel;
      channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
      channel.target_path = "pointer";
      tinygltf::Value::Object pointer;
      pointer["pointer"] = tinygltf::Value("/materials/" + std::to_string(l) + "/pbrMetallicRoughness/baseColorFactor");
      channel.target_extensions["KHR_animation_pointer"] = tinygltf::Value(pointer);
      animation.channels.push_back(channel);
    }
    model.extensionsUsed.push_back("KHR_animation_pointer");
  }
  if (!animation.channels.empty()) model.animations.push_back(animation);
  model.extensionsUsed.push_back("KHR_materials_unlit");
  if (quantized) {
    model.extensionsUsed.push_back("KHR_mesh_quantization");
    model.extensionsRequired.push_back("KHR_mesh_quantization");
  }
  return doc;
}

}  // namespace ib::gltf
