#pragma once
// Pipeline creation shared by the tracer and the renderer: descriptor set and pipeline layouts,
// compute pipelines, and ray tracing pipelines of the one shape both use: a ray generation
// shader, one miss shader and one procedural hit group (intersection + closest hit), with the
// shader binding table that launches them.

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "vk/buffer.hpp"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

// The words of a SPIR-V module embedded by shaders/CMakeLists.txt.
template <std::size_t N>
std::span<const std::uint32_t> spirv(const std::uint32_t (&words)[N]) {
  return {words, N};
}

// Bindings 0 to count - 1 (an AMRSTREAM_*_BINDING_COUNT), each one storage buffer seen by
// `stages`; a kernel retypes the others by index.
std::vector<VkDescriptorSetLayoutBinding> storageBufferBindings(std::uint32_t count,
                                                                VkShaderStageFlags stages);

UniqueHandle<VkDescriptorSetLayout> createDescriptorSetLayout(
    const Context& ctx, std::span<const VkDescriptorSetLayoutBinding> bindings);

// With `pushConstantBytes` > 0, one push-constant range at offset 0 for `pushConstantStages`.
UniqueHandle<VkPipelineLayout> createPipelineLayout(const Context& ctx,
                                                    VkDescriptorSetLayout setLayout,
                                                    std::uint32_t pushConstantBytes = 0,
                                                    VkShaderStageFlags pushConstantStages = 0);

UniqueHandle<VkPipeline> createComputePipeline(const Context& ctx, VkPipelineLayout layout,
                                               std::span<const std::uint32_t> spirv,
                                               const VkSpecializationInfo* specialization,
                                               std::string_view name);

struct ShaderBindingTable {
  Buffer buffer;
  VkStridedDeviceAddressRegionKHR raygen{};
  VkStridedDeviceAddressRegionKHR miss{};
  VkStridedDeviceAddressRegionKHR hit{};
  VkStridedDeviceAddressRegionKHR callable{};
};

struct ProceduralHitShaders {
  std::span<const std::uint32_t> raygen, miss, intersection, closestHit;
};

struct RayTracingPipeline {
  UniqueHandle<VkPipeline> pipeline;
  ShaderBindingTable bindingTable;
};

// Groups: 0 ray generation, 1 miss, 2 the procedural hit group. `raygenSpecialization` (may be
// null) applies to the ray generation shader only. Recursion depth 1.
RayTracingPipeline createProceduralRayTracingPipeline(
    const Context& ctx, VkPipelineLayout layout, const ProceduralHitShaders& shaders,
    const VkSpecializationInfo* raygenSpecialization, std::string_view name);

}  // namespace amrstream::vk
