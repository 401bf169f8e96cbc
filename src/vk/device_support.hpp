#pragma once
// What one physical device offers (API version, extensions, feature bits, a compute queue) and
// its properties, read once through the *2 queries. Holds no handles: plain data about a device.

#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vk/capability.hpp"

namespace amrstream::vk {

inline constexpr uint32_t kRequiredApiVersion = VK_API_VERSION_1_2;

struct DeviceSupport {
  uint32_t apiVersion = 0;
  std::vector<std::string> extensions;  // sorted
  std::optional<uint32_t> computeQueueFamily;
  bool scalarBlockLayout = false;
  bool bufferDeviceAddress = false;
  bool shaderInt64 = false;
  bool accelerationStructure = false;
  bool rayQuery = false;
  bool rayTracingPipeline = false;

  bool hasExtension(std::string_view name) const;
  bool has(Feature feature) const;
};

DeviceSupport probeSupport(VkPhysicalDevice physicalDevice);

// What the device lacks for `capability` alone, in the words a user can act on: extension names
// ("VK_KHR_ray_query"), "feature rayQuery", "Vulkan 1.2 (device offers 1.1.0)",
// "a compute queue". Empty when supported.
std::vector<std::string> missingFor(const DeviceSupport& support, Capability capability);

// Properties of interest. The extension structs stay zero unless the device has the extension;
// all pNext members are null (the chains used to fill them are gone).
struct DeviceProperties {
  VkPhysicalDeviceProperties core{};
  VkPhysicalDeviceDriverProperties driver{};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR accelerationStructure{};
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rayTracingPipeline{};
  VkDeviceSize maxMemoryAllocationSize = 0;
  VkPhysicalDeviceMemoryProperties memory{};
};

DeviceProperties queryProperties(VkPhysicalDevice physicalDevice, const DeviceSupport& support);

// "1.3.239".
std::string formatApiVersion(uint32_t version);

}  // namespace amrstream::vk
