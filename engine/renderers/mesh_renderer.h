// Draws a RenderMesh at the current positions with every active key's artwork blended by the
// weights (premultiplied alpha), near a key its rim (KeyRim) where the mesh drew nothing, then the
// overlays, into a render pass created by createColorRenderPass. Heavy setup once (artwork upload, UVs, indices, pipelines); per frame only
// positions (welded along glued cuts, with each vertex's closure: weldCuts) and overlay vertices
// are written, into the stream buffer of the frame's slot, so the GPU keeps drawing earlier slots
// meanwhile (libigl's precompute-then-solve, for pixels). The frame's sampling picks one of two
// descriptor sets made up front, one per sampler.
#pragma once

#include "gpu/gpu_resources.h"
#include "output/render_mesh.h"
#include "renderers/artwork_texture.h"
#include "renderers/renderer_pipelines.h"

#include <array>
#include <memory>
#include <vector>

namespace ib::render {

class MeshRenderer {
 public:
  // `pipelines` are the target's (its render pass and sample count: createRendererPipelines), shared
  // with the renderers of the meshes it draws before and after this one; `slots` is how many
  // frames may be in flight. Uploads the artwork (one array layer per key, premultiplied: the
  // mesh's texture when it has one) through `pool`. Throws VulkanError.
  MeshRenderer(const vk::VulkanContext& context, VkCommandPool pool, const RenderMesh& mesh,
               std::shared_ptr<const vk::RendererPipelines> pipelines, int slots);

  // Records `frame` into `cmd`, inside a begun render pass of `extent` pixels. Writes slot `slot`'s
  // stream buffer: the caller must know that slot's previous frame has finished. Throws
  // std::invalid_argument for positions or weights of the wrong size, negative or non-finite
  // weights, or too many onion skins.
  void record(VkCommandBuffer cmd, int slot, VkExtent2D extent, const FrameDraw& frame);

  int slots() const { return static_cast<int>(streams_.size()); }

 private:
  struct Active {
    int count = 0;
    float weights[kMaxActiveKeys] = {};
    int layers[kMaxActiveKeys] = {};
  };
  Active activeKeys(const Eigen::VectorXd& weights) const;
  // pixelsPerUnit: target pixels per drawing pixel, for weldCuts. stencil: this draw's reference
  // (1 + its index in the frame), which its mesh writes and its rim tests.
  void drawArtwork(VkCommandBuffer cmd, const float view[4], double pixelsPerUnit, const Eigen::MatrixX2d& x,
                   const Eigen::VectorXd& weights, const std::vector<char>* heldPairs, const float tint[4], int slot,
                   uint32_t stencil, VkDeviceSize& offset);
  void drawOverlays(VkCommandBuffer cmd, const float view[4], VkExtent2D extent, const FrameDraw& frame, int slot,
                    VkDeviceSize offset);

  int vertexCount_ = 0;
  int rimPoints_ = 0;                            // the key rim's points, streamed after the vertices
  int keyCount_ = 0;
  uint32_t indexCount_ = 0;
  uint32_t rimIndexCount_ = 0;                   // the rim's indices, after the mesh's
  KeyRim rim_;
  std::vector<Edge> edges_;                      // overlay geometry, copied from the RenderMesh
  std::vector<std::vector<Edge>> cohesiveEdges_;
  CutSides cutSides_;                                  // welded in every frame (weldCuts)
  CutInks inks_;                                       // the outline ink drawn where cuts open (inkFrame)
  std::vector<int> features_;
  VkDeviceSize overlayCapacity_ = 0;             // overlay vertices a stream buffer holds
  std::shared_ptr<const vk::RendererPipelines> pipelines_;  // never null
  vk::ArtworkTexture artwork_;
  vk::GpuBuffer uvs_;
  vk::GpuBuffer indices_;
  vk::DescriptorPoolObject descriptorPool_;
  static constexpr int kSamplings = 2;                 // render::Sampling's values
  std::array<VkDescriptorSet, kSamplings> descriptorSets_{};  // [Sampling]: artwork and UVs; freed with the pool
  std::vector<vk::GpuBuffer> streams_;              // [slot]: positions, then overlay vertices
};

}  // namespace ib::render
