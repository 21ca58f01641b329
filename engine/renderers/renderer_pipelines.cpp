#include "renderers/renderer_pipelines.h"

#include "gpu/gpu_resources.h"
#include "gpu/vulkan_check.h"

#include <artwork2_frag.h>
#include <artwork2_vert.h>
#include <artwork4_frag.h>
#include <artwork4_vert.h>
#include <artwork8_frag.h>
#include <artwork8_vert.h>
#include <overlay_frag.h>
#include <overlay_vert.h>
#include <sheet_frag.h>
#include <sheet_vert.h>

#include <array>
#include <cstddef>
#include <vector>

namespace ib::vk {

namespace {

// The artwork's set: {0: sampler2DArray, fragment stage} and, with `uvs`, {1: storage buffer, vertex stage}.
DescriptorSetLayoutObject createSetLayout(VkDevice device, bool uvs = true) {
  std::array<VkDescriptorSetLayoutBinding, 2> bindings{};
  bindings[0].binding = 0;
  bindings[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  bindings[0].descriptorCount = 1;
  bindings[0].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
  bindings[1].binding = 1;
  bindings[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  bindings[1].descriptorCount = 1;
  bindings[1].stageFlags = VK_SHADER_STAGE_VERTEX_BIT;
  VkDescriptorSetLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  info.bindingCount = uvs ? 2 : 1;
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout), "creating the artwork descriptor set layout");
  return DescriptorSetLayoutObject(device, layout);
}

PipelineLayoutObject createLayout(VkDevice device, const VkDescriptorSetLayout* set, uint32_t pushBytes,
                                  VkShaderStageFlags pushStages) {
  VkPushConstantRange push{pushStages, 0, pushBytes};
  VkPipelineLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  info.setLayoutCount = set ? 1 : 0;
  info.pSetLayouts = set;
  info.pushConstantRangeCount = 1;
  info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  check(vkCreatePipelineLayout(device, &info, nullptr, &layout), "creating a pipeline layout");
  return PipelineLayoutObject(device, layout);
}

struct PipelineSpec {
  const uint32_t* vertexWords;
  size_t vertexBytes;
  const uint32_t* fragmentWords;
  size_t fragmentBytes;
  const char* name;
  VkPrimitiveTopology topology;
  std::vector<VkVertexInputAttributeDescription> attributes;
  uint32_t stride;
  // What the pipeline does with the stencil: nothing; writes the draw's reference (dynamic) where it
  // draws; or draws only where the stencil is not yet the reference, writing it (each sample once).
  enum class Stencil { kNone, kWrite, kFirstOnly } stencil = Stencil::kNone;
};

PipelineObject createPipeline(VkDevice device, VkRenderPass pass, VkSampleCountFlagBits samples, VkPipelineLayout layout,
                              const PipelineSpec& spec) {
  const ShaderModuleObject vertex = createShaderModule(device, spec.vertexWords, spec.vertexBytes, spec.name);
  const ShaderModuleObject fragment = createShaderModule(device, spec.fragmentWords, spec.fragmentBytes, spec.name);
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0].sType = stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex.get();
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment.get();
  stages[1].pName = "main";
  VkVertexInputBindingDescription binding{0, spec.stride, VK_VERTEX_INPUT_RATE_VERTEX};
  VkPipelineVertexInputStateCreateInfo input{};
  input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  input.vertexBindingDescriptionCount = spec.attributes.empty() ? 0 : 1;  // none: positions from gl_VertexIndex
  input.pVertexBindingDescriptions = &binding;
  input.vertexAttributeDescriptionCount = static_cast<uint32_t>(spec.attributes.size());
  input.pVertexAttributeDescriptions = spec.attributes.data();
  VkPipelineInputAssemblyStateCreateInfo assembly{};
  assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  assembly.topology = spec.topology;
  VkPipelineViewportStateCreateInfo viewport{};
  viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{};
  multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  multisample.rasterizationSamples = samples;
  VkPipelineColorBlendAttachmentState blend{};
  blend.blendEnable = VK_TRUE;
  blend.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend.colorBlendOp = VK_BLEND_OP_ADD;
  blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend.alphaBlendOp = VK_BLEND_OP_ADD;
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                         VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blending{};
  blending.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  blending.attachmentCount = 1;
  blending.pAttachments = &blend;
  VkPipelineDepthStencilStateCreateInfo depthStencil{};
  depthStencil.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  if (spec.stencil != PipelineSpec::Stencil::kNone) {
    depthStencil.stencilTestEnable = VK_TRUE;
    VkStencilOpState op{};
    op.failOp = VK_STENCIL_OP_KEEP;
    op.passOp = VK_STENCIL_OP_REPLACE;
    op.depthFailOp = VK_STENCIL_OP_KEEP;
    op.compareOp = spec.stencil == PipelineSpec::Stencil::kWrite ? VK_COMPARE_OP_ALWAYS : VK_COMPARE_OP_NOT_EQUAL;
    op.compareMask = op.writeMask = 0xff;
    depthStencil.front = depthStencil.back = op;
  }
  const std::array<VkDynamicState, 3> dynamicStates{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                                    VK_DYNAMIC_STATE_STENCIL_REFERENCE};
  VkPipelineDynamicStateCreateInfo dynamic{};
  dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  dynamic.dynamicStateCount = spec.stencil == PipelineSpec::Stencil::kNone ? 2 : 3;
  dynamic.pDynamicStates = dynamicStates.data();
  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.stageCount = static_cast<uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pColorBlendState = &blending;
  info.pDepthStencilState = &depthStencil;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  info.renderPass = pass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        (std::string("creating the ") + spec.name + " pipeline").c_str());
  return PipelineObject(device, pipeline);
}

}  // namespace

int artworkVariant(int activeKeys) { return activeKeys <= 2 ? 0 : activeKeys <= 4 ? 1 : 2; }

RendererPipelines createRendererPipelines(VkDevice device, VkRenderPass pass, VkSampleCountFlagBits samples) {
  RendererPipelines out;
  out.setLayout = createSetLayout(device);
  const VkDescriptorSetLayout set = out.setLayout.get();
  out.artworkLayout = createLayout(device, &set, sizeof(ArtworkPush), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  out.overlayLayout = createLayout(device, nullptr, 4 * sizeof(float), VK_SHADER_STAGE_VERTEX_BIT);
  const std::vector<VkVertexInputAttributeDescription> artworkInput = {
      {0, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(ArtworkVertex, position)},
      {1, 0, VK_FORMAT_R32_SFLOAT, offsetof(ArtworkVertex, seamClosure)},
      {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(ArtworkVertex, inkDistance)},
      {3, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(ArtworkVertex, inkColour)}};
  const PipelineSpec artwork[3] = {
      {artwork2_vert, sizeof(artwork2_vert), artwork2_frag, sizeof(artwork2_frag), "artwork (2 keys)",
       VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, artworkInput, sizeof(ArtworkVertex)},
      {artwork4_vert, sizeof(artwork4_vert), artwork4_frag, sizeof(artwork4_frag), "artwork (4 keys)",
       VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, artworkInput, sizeof(ArtworkVertex)},
      {artwork8_vert, sizeof(artwork8_vert), artwork8_frag, sizeof(artwork8_frag), "artwork (8 keys)",
       VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, artworkInput, sizeof(ArtworkVertex)}};
  for (int v = 0; v < 3; ++v) {
    PipelineSpec spec = artwork[v];
    spec.stencil = PipelineSpec::Stencil::kWrite;
    out.artwork[v] = createPipeline(device, pass, samples, out.artworkLayout.get(), spec);
    spec.stencil = PipelineSpec::Stencil::kFirstOnly;
    out.rim[v] = createPipeline(device, pass, samples, out.artworkLayout.get(), spec);
  }
  PipelineSpec overlay{overlay_vert, sizeof(overlay_vert), overlay_frag, sizeof(overlay_frag), "overlay lines",
                       VK_PRIMITIVE_TOPOLOGY_LINE_LIST,
                       {{0, 0, VK_FORMAT_R32G32_SFLOAT, 0}, {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 2 * sizeof(float)}},
                       sizeof(OverlayVertex)};
  out.overlayLines = createPipeline(device, pass, samples, out.overlayLayout.get(), overlay);
  overlay.name = "overlay triangles";
  overlay.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  out.overlayTriangles = createPipeline(device, pass, samples, out.overlayLayout.get(), overlay);
  return out;
}

SheetPipeline createSheetPipeline(VkDevice device, VkRenderPass pass, VkSampleCountFlagBits samples) {
  SheetPipeline out;
  out.setLayout = createSetLayout(device, false);
  const VkDescriptorSetLayout set = out.setLayout.get();
  out.layout = createLayout(device, &set, sizeof(SheetPush), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  const PipelineSpec sheet{sheet_vert, sizeof(sheet_vert), sheet_frag, sizeof(sheet_frag), "drawing sheet",
                           VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, {}, 0};
  out.pipeline = createPipeline(device, pass, samples, out.layout.get(), sheet);
  return out;
}

}  // namespace ib::vk
