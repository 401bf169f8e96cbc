#include "vk/device_functions.hpp"

#include <fmt/format.h>

#include "vk/vk_error.hpp"

namespace amrstream::vk {
namespace {

template <typename Function>
void loadFromDevice(VkDevice device, Function& function) {
  function.set(
      reinterpret_cast<typename Function::Pointer>(vkGetDeviceProcAddr(device, function.name())));
  if (!function) {
    throw VulkanError(VK_ERROR_EXTENSION_NOT_PRESENT,
                      fmt::format("vkGetDeviceProcAddr returned no {} although {} is enabled",
                                  function.name(), function.extension()));
  }
}

template <typename Function>
void loadFromInstance(VkInstance instance, Function& function) {
  function.set(reinterpret_cast<typename Function::Pointer>(
      vkGetInstanceProcAddr(instance, function.name())));
  if (!function) {
    throw VulkanError(VK_ERROR_EXTENSION_NOT_PRESENT,
                      fmt::format("vkGetInstanceProcAddr returned no {} although {} is enabled",
                                  function.name(), function.extension()));
  }
}

}  // namespace

void throwFunctionNotLoaded(const char* function, const char* extension) {
  throw VulkanError(VK_ERROR_EXTENSION_NOT_PRESENT,
                    fmt::format("{} called, but {} is not enabled on this context (request the "
                                "capability that needs it from ContextBuilder)",
                                function, extension));
}

DeviceFunctions DeviceFunctions::load(VkDevice device, bool accelerationStructure,
                                      bool rayTracingPipeline) {
  DeviceFunctions f;
  if (accelerationStructure) {
    loadFromDevice(device, f.vkCreateAccelerationStructureKHR);
    loadFromDevice(device, f.vkDestroyAccelerationStructureKHR);
    loadFromDevice(device, f.vkGetAccelerationStructureBuildSizesKHR);
    loadFromDevice(device, f.vkCmdBuildAccelerationStructuresKHR);
    loadFromDevice(device, f.vkGetAccelerationStructureDeviceAddressKHR);
    loadFromDevice(device, f.vkCmdWriteAccelerationStructuresPropertiesKHR);
    loadFromDevice(device, f.vkCmdCopyAccelerationStructureKHR);
  }
  if (rayTracingPipeline) {
    loadFromDevice(device, f.vkCreateRayTracingPipelinesKHR);
    loadFromDevice(device, f.vkGetRayTracingShaderGroupHandlesKHR);
    loadFromDevice(device, f.vkCmdTraceRaysKHR);
  }
  return f;
}

InstanceFunctions InstanceFunctions::load(VkInstance instance, bool debugUtils) {
  InstanceFunctions f;
  if (debugUtils) {
    loadFromInstance(instance, f.vkCreateDebugUtilsMessengerEXT);
    loadFromInstance(instance, f.vkDestroyDebugUtilsMessengerEXT);
    loadFromInstance(instance, f.vkSetDebugUtilsObjectNameEXT);
  }
  return f;
}

}  // namespace amrstream::vk
