#pragma once
// A VkShaderModule from SPIR-V words (the `const uint32_t[]` arrays that glslangValidator --vn
// embeds at build time).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

// Throws std::invalid_argument when `spirv` is empty or does not start with the SPIR-V magic
// number, VulkanError when the driver refuses it.
UniqueHandle<VkShaderModule> createShaderModule(const Context& ctx, std::span<const uint32_t> spirv,
                                                std::string_view name);

}  // namespace amrstream::vk
