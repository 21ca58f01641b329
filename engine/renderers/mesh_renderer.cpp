#include "renderers/mesh_renderer.h"

#include "gpu/vulkan_check.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>

namespace ib::render {

namespace {

constexpr float kWireframe[4] = {0.25f, 0.4f, 0.6f, 0.7f};    // premultiplied: steel blue, 70% opaque
constexpr float kCohesive[4] = {0.9f, 0.1f, 0.1f, 1.0f};       // red
constexpr float kFeature[4] = {0.1f, 0.3f, 0.95f, 1.0f};       // blue
constexpr int kSquareCorners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};  // two triangles

// clip = p * view.xy + view.zw maps the view box onto [-1, 1]^2 (Vulkan's y points down, like drawings').
void viewTransform(const ViewBox& box, float out[4]) {
  const double sx = 2.0 / (box.x1 - box.x0), sy = 2.0 / (box.y1 - box.y0);
  out[0] = static_cast<float>(sx);
  out[1] = static_cast<float>(sy);
  out[2] = static_cast<float>(-1.0 - box.x0 * sx);
  out[3] = static_cast<float>(-1.0 - box.y0 * sy);
}

// `sets` sets of the artwork layout: one combined image sampler and one storage buffer each.
vk::DescriptorPoolObject createDescriptorPool(VkDevice device, uint32_t sets) {
  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, sets},
                                         {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, sets}};
  VkDescriptorPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  info.maxSets = sets;
  info.poolSizeCount = 2;
  info.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  vk::check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "creating the descriptor pool");
  return vk::DescriptorPoolObject(device, pool);
}

void pushVertex(vk::OverlayVertex*& out, double x, double y, const float colour[4]) {
  *out++ = {{static_cast<float>(x), static_cast<float>(y)}, {colour[0], colour[1], colour[2], colour[3]}};
}

}  // namespace

MeshRenderer::MeshRenderer(const vk::VulkanContext& context, VkCommandPool pool, const RenderMesh& mesh,
                           std::shared_ptr<const vk::RendererPipelines> pipelines, int slots)
    : vertexCount_(mesh.vertexCount),
      rimPoints_(static_cast<int>(mesh.rim.points.size())),
      keyCount_(static_cast<int>(mesh.keyUV.size())),
      indexCount_(static_cast<uint32_t>(3 * mesh.triangles.size())),
      rimIndexCount_(static_cast<uint32_t>(3 * mesh.rim.triangles.size())),
      rim_(mesh.rim),
      edges_(mesh.edges),
      cohesiveEdges_(mesh.cohesiveEdges),
      cutSides_(mesh.cutSides),
      inks_(mesh.inks),
      features_(mesh.features),
      pipelines_(std::move(pipelines)) {
  if (!pipelines_) throw std::invalid_argument("render: no pipelines");
  if (keyCount_ == 0 || vertexCount_ == 0 || mesh.triangles.empty()) throw std::invalid_argument("render: the mesh is empty");
  VkDevice device = context.device();
  if (mesh.drawings.size() != mesh.artwork.size() || mesh.rimUV.size() != mesh.keyUV.size())
    throw std::invalid_argument("render: the mesh's drawings or rim do not match its keys");
  artwork_ = mesh.texture ? vk::uploadArtwork(context, pool, *mesh.texture) : vk::uploadArtwork(context, pool, textureLayers(mesh));
  // UVs vertex-major ((n + rim points) x m vec2), scaled from each drawing's size to the shared layer size.
  const int points = vertexCount_ + rimPoints_;
  std::vector<float> uv(2 * static_cast<size_t>(points) * keyCount_);
  for (int k = 0; k < keyCount_; ++k) {
    const float su = static_cast<float>(mesh.artwork[k].width) / artwork_.layerSize.width;
    const float sv = static_cast<float>(mesh.artwork[k].height) / artwork_.layerSize.height;
    for (int v = 0; v < points; ++v) {
      const bool onRim = v >= vertexCount_;
      const Eigen::MatrixX2f& from = onRim ? mesh.rimUV[k] : mesh.keyUV[k];
      const int row = onRim ? v - vertexCount_ : v;
      uv[2 * (static_cast<size_t>(v) * keyCount_ + k)] = from(row, 0) * su;
      uv[2 * (static_cast<size_t>(v) * keyCount_ + k) + 1] = from(row, 1) * sv;
    }
  }
  // Host-visible, written in place: no copy on the queue for the window to wait on after a reload.
  uvs_ = vk::createBuffer(context, uv.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "the UV buffer");
  std::memcpy(uvs_.mapped, uv.data(), uv.size() * sizeof(float));
  std::vector<uint32_t> index;
  for (const Triangle& t : mesh.triangles)
    for (int c : t) index.push_back(static_cast<uint32_t>(c));
  for (const Triangle& t : mesh.rim.triangles)
    for (int c : t) index.push_back(static_cast<uint32_t>(c));
  indices_ = vk::createBuffer(context, index.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, true,
                              "the index buffer");
  std::memcpy(indices_.mapped, index.data(), index.size() * sizeof(uint32_t));
  // One set per sampler (Sampling), each with the artwork and the UVs.
  descriptorPool_ = createDescriptorPool(device, kSamplings);
  const VkDescriptorSetLayout layouts[kSamplings] = {pipelines_->setLayout.get(), pipelines_->setLayout.get()};
  VkDescriptorSetAllocateInfo allocate{};
  allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  allocate.descriptorPool = descriptorPool_.get();
  allocate.descriptorSetCount = kSamplings;
  allocate.pSetLayouts = layouts;
  vk::check(vkAllocateDescriptorSets(device, &allocate, descriptorSets_.data()), "allocating the artwork descriptor sets");
  const VkSampler samplers[kSamplings] = {artwork_.linear.get(), artwork_.nearest.get()};  // [Sampling]
  VkDescriptorImageInfo images[kSamplings];
  const VkDescriptorBufferInfo buffer{uvs_.buffer.get(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet writes[2 * kSamplings] = {};
  for (int s = 0; s < kSamplings; ++s) {
    images[s] = {samplers[s], artwork_.image.view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet& image = writes[2 * s];
    VkWriteDescriptorSet& uvs = writes[2 * s + 1];
    image.sType = uvs.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    image.dstSet = uvs.dstSet = descriptorSets_[s];
    image.dstBinding = 0;
    image.descriptorCount = 1;
    image.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    image.pImageInfo = &images[s];
    uvs.dstBinding = 1;
    uvs.descriptorCount = 1;
    uvs.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    uvs.pBufferInfo = &buffer;
  }
  vkUpdateDescriptorSets(device, 2 * kSamplings, writes, 0, nullptr);
  // Per slot: every onion skin's and the frame's positions, then the largest overlay.
  size_t cohesive = 0;
  for (const auto& c : cohesiveEdges_) cohesive += c.size();
  overlayCapacity_ = 2 * (edges_.size() + cohesive) + 6 * features_.size();
  const VkDeviceSize bytes = (1 + kMaxOnionSkins) * static_cast<VkDeviceSize>(points) * sizeof(vk::ArtworkVertex) +
                             std::max<VkDeviceSize>(1, overlayCapacity_) * sizeof(vk::OverlayVertex);
  for (int s = 0; s < slots; ++s)
    streams_.push_back(vk::createBuffer(context, bytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, true, "a vertex stream buffer"));
}

MeshRenderer::Active MeshRenderer::activeKeys(const Eigen::VectorXd& weights) const {
  if (weights.size() != keyCount_)
    throw std::invalid_argument("render: " + std::to_string(weights.size()) + " weights for " + std::to_string(keyCount_) + " keys");
  std::vector<int> order;
  for (int k = 0; k < keyCount_; ++k) {
    if (!std::isfinite(weights[k]) || weights[k] < 0)
      throw std::invalid_argument("render: weight " + std::to_string(k) + " is negative or not finite");
    if (weights[k] > 0) order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return weights[a] > weights[b]; });
  if (order.size() > static_cast<size_t>(kMaxActiveKeys)) order.resize(kMaxActiveKeys);
  double sum = 0;
  for (int k : order) sum += weights[k];
  Active active;
  for (int k : order) {
    active.weights[active.count] = static_cast<float>(weights[k] / sum);
    active.layers[active.count++] = k;
  }
  return active;
}

void MeshRenderer::drawArtwork(VkCommandBuffer cmd, const float view[4], double pixelsPerUnit, const Eigen::MatrixX2d& x,
                               const Eigen::VectorXd& weights, const std::vector<char>* heldPairs, const float tint[4],
                               int slot, uint32_t stencil, VkDeviceSize& offset) {
  if (x.rows() != vertexCount_)
    throw std::invalid_argument("render: " + std::to_string(x.rows()) + " positions for " + std::to_string(vertexCount_) + " vertices");
  if (!x.allFinite()) throw std::invalid_argument("render: positions are not finite");
  const Active active = activeKeys(weights);
  if (active.count == 0) return;  // nothing has weight: nothing to draw
  // At and near a key its drawing is the truth: a cut it draws a hair open stays so. The weld fades
  // out as the keys' own drawings fade in (keyness), and is gone at w = e_i.
  const double shown = keyness(Eigen::Map<const Eigen::VectorXf>(active.weights, active.count).cast<double>());
  CutWeld weld = weldCuts(x, cutSides_, pixelsPerUnit, {}, heldPairs);
  if (shown > 0) weld.positions += shown * (x - weld.positions);
  const InkFrame ink = inkFrame(inks_, x, weld.closure, weights, pixelsPerUnit);
  auto* out = reinterpret_cast<vk::ArtworkVertex*>(static_cast<char*>(streams_[slot].mapped) + offset);
  for (int v = 0; v < vertexCount_; ++v) {
    vk::ArtworkVertex& o = out[v];
    o.position[0] = static_cast<float>(weld.positions(v, 0));
    o.position[1] = static_cast<float>(weld.positions(v, 1));
    o.seamClosure = weld.closure[v];
    o.inkDistance = ink.distance[v];
    o.inkWidth = ink.width[v];
    o.inkAlpha = ink.alpha[v];
    for (int c = 0; c < 3; ++c) o.inkColour[c] = ink.colour[v][c];
  }
  vk::ArtworkPush push{};
  std::copy(view, view + 4, push.view);
  std::copy(tint, tint + 4, push.tint);
  std::copy(active.weights, active.weights + kMaxActiveKeys, push.weights);
  std::copy(active.layers, active.layers + kMaxActiveKeys, push.layers);
  push.activeCount = active.count;
  push.keyCount = keyCount_;
  push.keyness = static_cast<float>(shown);
  // The rim's points, offsets of the welded boundary (no seam, no ink).
  const bool rim = push.keyness > 0 && rimIndexCount_ > 0;
  if (rim) {
    const Eigen::MatrixX2d points = rimPoints(rim_, weld.positions);
    for (int j = 0; j < rimPoints_; ++j) {
      vk::ArtworkVertex& o = out[vertexCount_ + j];
      o = vk::ArtworkVertex{};
      o.position[0] = static_cast<float>(points(j, 0));
      o.position[1] = static_cast<float>(points(j, 1));
    }
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->artwork[vk::artworkVariant(active.count)].get());
  vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, stencil);
  vkCmdPushConstants(cmd, pipelines_->artworkLayout.get(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof push, &push);
  const VkBuffer buffer = streams_[slot].buffer.get();
  vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
  vkCmdBindIndexBuffer(cmd, indices_.buffer.get(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, indexCount_, 1, 0, 0, 0);
  if (rim) {
    push.rim = 1;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->rim[vk::artworkVariant(active.count)].get());
    vkCmdPushConstants(cmd, pipelines_->artworkLayout.get(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof push, &push);
    vkCmdDrawIndexed(cmd, rimIndexCount_, 1, indexCount_, 0, 0);
  }
  offset += static_cast<VkDeviceSize>(vertexCount_ + rimPoints_) * sizeof(vk::ArtworkVertex);
}

void MeshRenderer::drawOverlays(VkCommandBuffer cmd, const float view[4], VkExtent2D extent, const FrameDraw& frame, int slot,
                                VkDeviceSize offset) {
  const Overlays& o = frame.overlays;
  const Eigen::MatrixX2d& x = *frame.positions;
  auto* const first = reinterpret_cast<vk::OverlayVertex*>(static_cast<char*>(streams_[slot].mapped) + offset);
  vk::OverlayVertex* out = first;
  auto line = [&](const Edge& e, const float colour[4]) {
    pushVertex(out, x(e[0], 0), x(e[0], 1), colour);
    pushVertex(out, x(e[1], 0), x(e[1], 1), colour);
  };
  if (o.wireframe)
    for (const Edge& e : edges_) line(e, kWireframe);
  if (o.cohesive)
    for (int k = 0; k < keyCount_; ++k)
      if (frame.weights[k] > 0)
        for (const Edge& e : cohesiveEdges_[k]) line(e, kCohesive);
  const uint32_t lineVertices = static_cast<uint32_t>(out - first);
  if (o.features) {
    // A square of featureSize target pixels: half its side in drawing pixels along x and y.
    const double hx = 0.5 * o.featureSize / (extent.width * 0.5 * view[0]);
    const double hy = 0.5 * o.featureSize / (extent.height * 0.5 * view[1]);
    for (int f : features_) {
      const double cx = x(f, 0), cy = x(f, 1);
      for (const auto& corner : kSquareCorners) pushVertex(out, cx + corner[0] * hx, cy + corner[1] * hy, kFeature);
    }
  }
  const uint32_t triangleVertices = static_cast<uint32_t>(out - first) - lineVertices;
  if (lineVertices + triangleVertices == 0) return;
  const VkBuffer buffer = streams_[slot].buffer.get();
  vkCmdPushConstants(cmd, pipelines_->overlayLayout.get(), VK_SHADER_STAGE_VERTEX_BIT, 0, 4 * sizeof(float), view);
  vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
  if (lineVertices) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->overlayLines.get());
    vkCmdDraw(cmd, lineVertices, 1, 0, 0);
  }
  if (triangleVertices) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->overlayTriangles.get());
    vkCmdDraw(cmd, triangleVertices, 1, lineVertices, 0);
  }
}

void MeshRenderer::record(VkCommandBuffer cmd, int slot, VkExtent2D extent, const FrameDraw& frame) {
  if (slot < 0 || slot >= slots()) throw std::out_of_range("render: stream slot out of range");
  if (!frame.positions) throw std::invalid_argument("render: no positions to draw");
  if (frame.onion.size() > static_cast<size_t>(kMaxOnionSkins))
    throw std::invalid_argument("render: at most " + std::to_string(kMaxOnionSkins) + " onion skins");
  if (!(frame.view.x1 > frame.view.x0 && frame.view.y1 > frame.view.y0)) throw std::invalid_argument("render: the view box is empty");
  float view[4];
  viewTransform(frame.view, view);
  // Target pixels per drawing pixel (the larger of x's and y's when the view stretches one).
  const double pixelsPerUnit = std::max(extent.width / (frame.view.x1 - frame.view.x0),
                                        extent.height / (frame.view.y1 - frame.view.y0));
  // The frame's sampler, for its onion skins and itself (the overlay pipelines use no sets).
  const VkDescriptorSet set = descriptorSets_[frame.sampling == Sampling::kNearest ? 1 : 0];
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->artworkLayout.get(), 0, 1, &set, 0, nullptr);
  VkDeviceSize offset = 0;
  uint32_t stencil = 0;
  for (const OnionSkin& skin : frame.onion) {
    if (!skin.positions) throw std::invalid_argument("render: an onion skin has no positions");
    const float o = std::clamp(skin.opacity, 0.0f, 1.0f);
    const float tint[4] = {skin.tint[0] * o, skin.tint[1] * o, skin.tint[2] * o, o};
    drawArtwork(cmd, view, pixelsPerUnit, *skin.positions, skin.weights, skin.heldPairs, tint, slot, ++stencil, offset);
  }
  const float plain[4] = {1, 1, 1, 1};
  drawArtwork(cmd, view, pixelsPerUnit, *frame.positions, frame.weights, frame.heldPairs, plain, slot, ++stencil, offset);
  offset = (1 + kMaxOnionSkins) * static_cast<VkDeviceSize>(vertexCount_ + rimPoints_) * sizeof(vk::ArtworkVertex);
  drawOverlays(cmd, view, extent, frame, slot, offset);
}

}  // namespace ib::render
