#pragma once
// Creation of the VkInstance (API 1.2), with the Khronos validation layer and a debug-utils
// messenger chained in when asked. Shared by ContextBuilder and listDevices().

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "vk/unique_handle.hpp"
#include "vk/validation_log.hpp"

namespace amrstream::vk {

inline constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

struct InstanceOptions {
  bool validation = false;
  // Adds the layer's synchronization validation (missing or wrong barriers); needs validation.
  bool synchronizationValidation = false;
  // Enables VK_EXT_debug_utils for object names even without validation.
  bool debugUtils = false;
  // Receives the messages of instance creation and destruction; required with validation.
  ValidationLog* log = nullptr;
  // Required beyond those above, such as the surface extensions a window system needs.
  std::vector<std::string> extensions;
};

struct Instance {
  UniqueHandle<VkInstance> handle;
  bool debugUtilsEnabled = false;
};

// Throws ContextError naming what is missing (a Vulkan 1.2 loader, the validation layer, a
// required instance extension, a driver).
Instance createInstance(const InstanceOptions& options);

std::vector<VkPhysicalDevice> enumeratePhysicalDevices(VkInstance instance);

}  // namespace amrstream::vk
