#include "vk/device_support.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "vk/vk_error.hpp"

namespace amrstream::vk {

bool DeviceSupport::hasExtension(std::string_view name) const {
  return std::binary_search(extensions.begin(), extensions.end(), name);
}

bool DeviceSupport::has(Feature feature) const {
  switch (feature) {
    case Feature::ScalarBlockLayout:
      return scalarBlockLayout;
    case Feature::BufferDeviceAddress:
      return bufferDeviceAddress;
    case Feature::AccelerationStructure:
      return accelerationStructure;
    case Feature::RayQuery:
      return rayQuery;
    case Feature::RayTracingPipeline:
      return rayTracingPipeline;
  }
  return false;
}

DeviceSupport probeSupport(VkPhysicalDevice physicalDevice) {
  DeviceSupport support;
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(physicalDevice, &properties);
  support.apiVersion = properties.apiVersion;

  uint32_t count = 0;
  AMRSTREAM_VK_CHECK(
      vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> extensions(count);
  AMRSTREAM_VK_CHECK(
      vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &count, extensions.data()));
  for (const auto& e : extensions) support.extensions.emplace_back(e.extensionName);
  std::sort(support.extensions.begin(), support.extensions.end());

  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
  for (uint32_t i = 0; i < familyCount; ++i) {
    if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) != 0 && families[i].queueCount > 0) {
      support.computeQueueFamily = i;
      break;
    }
  }

  // Chain only the structs of what the device has: structs of absent extensions are invalid
  // in the pNext chain, and Vulkan12Features needs a 1.2 device.
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR accel{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  void** next = &features.pNext;
  auto chain = [&next](auto& s) {
    *next = &s;
    next = &s.pNext;
  };
  const bool is12 = support.apiVersion >= kRequiredApiVersion;
  if (is12) chain(vulkan12);
  if (support.hasExtension(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME)) chain(accel);
  if (support.hasExtension(VK_KHR_RAY_QUERY_EXTENSION_NAME)) chain(rayQuery);
  if (support.hasExtension(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME)) chain(pipeline);
  vkGetPhysicalDeviceFeatures2(physicalDevice, &features);

  support.shaderInt64 = features.features.shaderInt64 == VK_TRUE;
  support.scalarBlockLayout = is12 && vulkan12.scalarBlockLayout == VK_TRUE;
  support.bufferDeviceAddress = is12 && vulkan12.bufferDeviceAddress == VK_TRUE;
  support.accelerationStructure = accel.accelerationStructure == VK_TRUE;
  support.rayQuery = rayQuery.rayQuery == VK_TRUE;
  support.rayTracingPipeline = pipeline.rayTracingPipeline == VK_TRUE;
  return support;
}

std::vector<std::string> missingFor(const DeviceSupport& support, Capability capability) {
  std::vector<std::string> missing;
  if (support.apiVersion < kRequiredApiVersion) {
    missing.push_back(
        fmt::format("Vulkan 1.2 (device offers {})", formatApiVersion(support.apiVersion)));
  }
  if (!support.computeQueueFamily) missing.emplace_back("a compute queue");
  const Requirements requirements = requirementsOf(capability);
  for (const char* extension : requirements.extensions) {
    if (!support.hasExtension(extension)) missing.emplace_back(extension);
  }
  // A feature of a missing extension is not worth a second line.
  if (missing.empty()) {
    for (Feature feature : requirements.features) {
      if (!support.has(feature)) missing.push_back(fmt::format("feature {}", featureName(feature)));
    }
  }
  // No acceleration structure can be built unless rayQuery or rayTracingPipeline is enabled
  // (VUID-vkGetAccelerationStructureBuildSizesKHR-rayTracingPipeline-03617 and its siblings).
  const bool rayQuery = support.hasExtension(VK_KHR_RAY_QUERY_EXTENSION_NAME) && support.rayQuery;
  const bool pipeline = support.hasExtension(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME) &&
                        support.rayTracingPipeline;
  if (capability == Capability::AccelerationStructure && !rayQuery && !pipeline) {
    missing.push_back(fmt::format("{} or {}", VK_KHR_RAY_QUERY_EXTENSION_NAME,
                                  VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME));
  }
  return missing;
}

DeviceProperties queryProperties(VkPhysicalDevice physicalDevice, const DeviceSupport& support) {
  DeviceProperties result;
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  VkPhysicalDeviceMaintenance3Properties maintenance3{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  result.driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
  result.accelerationStructure.sType =
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR;
  result.rayTracingPipeline.sType =
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR;

  void** next = &properties.pNext;
  auto chain = [&next](auto& s) {
    *next = &s;
    next = &s.pNext;
  };
  chain(maintenance3);
  if (support.apiVersion >= kRequiredApiVersion ||
      support.hasExtension(VK_KHR_DRIVER_PROPERTIES_EXTENSION_NAME)) {
    chain(result.driver);
  }
  if (support.hasExtension(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME)) {
    chain(result.accelerationStructure);
  }
  if (support.hasExtension(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME)) {
    chain(result.rayTracingPipeline);
  }
  vkGetPhysicalDeviceProperties2(physicalDevice, &properties);
  vkGetPhysicalDeviceMemoryProperties(physicalDevice, &result.memory);

  result.core = properties.properties;
  result.maxMemoryAllocationSize = maintenance3.maxMemoryAllocationSize;
  result.driver.pNext = nullptr;
  result.accelerationStructure.pNext = nullptr;
  result.rayTracingPipeline.pNext = nullptr;
  return result;
}

std::string formatApiVersion(uint32_t version) {
  return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(version), VK_API_VERSION_MINOR(version),
                     VK_API_VERSION_PATCH(version));
}

}  // namespace amrstream::vk
