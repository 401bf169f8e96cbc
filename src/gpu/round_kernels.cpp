#include "round_kernels.hpp"

#include "../../shaders/glsl/shared/round_bindings.h"
#include "../../shaders/glsl/shared/round_params.h"
#include "compact_round_comp.h"
#include "point_data_comp.h"
#include "scan_blocks_comp.h"
#include "scan_lines_comp.h"
#include "vk/context.hpp"
#include "vk/pipelines.hpp"

namespace amrstream::gpu {

namespace {

vk::UniqueHandle<VkDescriptorSetLayout> storageBufferLayout(const vk::Context& ctx,
                                                            std::uint32_t count) {
  return vk::createDescriptorSetLayout(
      ctx, vk::storageBufferBindings(count, VK_SHADER_STAGE_COMPUTE_BIT));
}

}  // namespace

RoundKernels createRoundKernels(const vk::Context& ctx) {
  using vk::spirv;
  RoundKernels k;
  k.compactionSetLayout = storageBufferLayout(ctx, AMRSTREAM_COMPACTION_BINDING_COUNT);
  k.compactionLayout =
      vk::createPipelineLayout(ctx, k.compactionSetLayout.get(), sizeof(shared::CompactionParams),
                               VK_SHADER_STAGE_COMPUTE_BIT);
  k.scanLines = vk::createComputePipeline(
      ctx, k.compactionLayout.get(), spirv(amrstream_spirv_scan_lines_comp), nullptr, "scan lines");
  k.scanBlocks =
      vk::createComputePipeline(ctx, k.compactionLayout.get(),
                                spirv(amrstream_spirv_scan_blocks_comp), nullptr, "scan blocks");
  k.compact = vk::createComputePipeline(ctx, k.compactionLayout.get(),
                                        spirv(amrstream_spirv_compact_round_comp), nullptr,
                                        "compact round");
  k.pointDataSetLayout = storageBufferLayout(ctx, AMRSTREAM_POINT_DATA_BINDING_COUNT);
  k.pointDataLayout =
      vk::createPipelineLayout(ctx, k.pointDataSetLayout.get(), sizeof(shared::PointDataParams),
                               VK_SHADER_STAGE_COMPUTE_BIT);
  k.pointData = vk::createComputePipeline(
      ctx, k.pointDataLayout.get(), spirv(amrstream_spirv_point_data_comp), nullptr, "point data");
  return k;
}

}  // namespace amrstream::gpu
