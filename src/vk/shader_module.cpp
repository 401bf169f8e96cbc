#include "vk/shader_module.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

UniqueHandle<VkShaderModule> createShaderModule(const Context& ctx, std::span<const uint32_t> spirv,
                                                std::string_view name) {
  constexpr uint32_t kSpirvMagic = 0x07230203;
  if (spirv.empty() || spirv.front() != kSpirvMagic) {
    throw std::invalid_argument(
        fmt::format("shader '{}' is not SPIR-V (empty or no magic number)", name));
  }
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateShaderModule(ctx.device(), &info, nullptr, &module));
  UniqueHandle<VkShaderModule> owned(ctx.device(), module);
  setDebugName(ctx, module, name);
  return owned;
}

}  // namespace amrstream::vk
