#include "vk/debug_names.hpp"

#include <string>

#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

void setDebugName(const Context& ctx, VkObjectType type, uint64_t handle, std::string_view name) {
  if (!ctx.debugUtilsEnabled() || handle == 0) return;
  const std::string terminated(name);
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = terminated.c_str();
  AMRSTREAM_VK_CHECK(ctx.instanceFunctions().vkSetDebugUtilsObjectNameEXT(ctx.device(), &info));
}

}  // namespace amrstream::vk
