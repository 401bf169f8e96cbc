#pragma once
// Extension entry points, loaded at run time. Debian's loader (libvulkan 1.3.239) exports no
// acceleration-structure or ray-tracing symbols, so they must come from vkGetDeviceProcAddr; the
// debug-utils ones come from vkGetInstanceProcAddr. Only the functions of enabled extensions are
// loaded. Calling one that was not loaded throws a VulkanError naming the function and the
// extension (and never jumps through a null pointer).
//
// The members carry the Vulkan names, so `ctx.functions().vkCmdTraceRaysKHR(cmd, ...)` reads like
// the specification.

#include <vulkan/vulkan.h>

namespace amrstream::vk {

[[noreturn]] void throwFunctionNotLoaded(const char* function, const char* extension);

template <typename Pointer>
class LoadedFunction;

// One entry point: its name, the extension that provides it and, once loaded, its address.
template <typename R, typename... Args>
class LoadedFunction<R(VKAPI_PTR*)(Args...)> {
 public:
  using Pointer = R(VKAPI_PTR*)(Args...);

  constexpr LoadedFunction(const char* name, const char* extension)
      : name_(name), extension_(extension) {}

  R operator()(Args... args) const {
    if (pointer_ == nullptr) throwFunctionNotLoaded(name_, extension_);
    return pointer_(args...);
  }

  explicit operator bool() const { return pointer_ != nullptr; }
  Pointer get() const { return pointer_; }
  const char* name() const { return name_; }
  const char* extension() const { return extension_; }
  void set(Pointer pointer) { pointer_ = pointer; }

 private:
  const char* name_;
  const char* extension_;
  Pointer pointer_ = nullptr;
};

#define AMRSTREAM_VK_FUNCTION(name, extension) \
  LoadedFunction<PFN_##name> name { #name, extension }

// Device-level extension functions. Copyable: it holds addresses only, valid while the device
// that loaded them lives.
struct DeviceFunctions {
  // Loads the functions of each enabled extension; throws VulkanError when the driver does not
  // return one of them although the extension was enabled.
  static DeviceFunctions load(VkDevice device, bool accelerationStructure, bool rayTracingPipeline);

  // VK_KHR_acceleration_structure
  AMRSTREAM_VK_FUNCTION(vkCreateAccelerationStructureKHR,
                        VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkDestroyAccelerationStructureKHR,
                        VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkGetAccelerationStructureBuildSizesKHR,
                        VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkCmdBuildAccelerationStructuresKHR,
                        VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkGetAccelerationStructureDeviceAddressKHR,
                        VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkCmdWriteAccelerationStructuresPropertiesKHR,
                        VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkCmdCopyAccelerationStructureKHR,
                        VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
  // VK_KHR_ray_tracing_pipeline
  AMRSTREAM_VK_FUNCTION(vkCreateRayTracingPipelinesKHR, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkGetRayTracingShaderGroupHandlesKHR,
                        VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkCmdTraceRaysKHR, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
};

// Instance-level VK_EXT_debug_utils functions (vkSetDebugUtilsObjectNameEXT is dispatched on the
// device but is an instance extension's command, so it is loaded here).
struct InstanceFunctions {
  static InstanceFunctions load(VkInstance instance, bool debugUtils);

  AMRSTREAM_VK_FUNCTION(vkCreateDebugUtilsMessengerEXT, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkDestroyDebugUtilsMessengerEXT, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  AMRSTREAM_VK_FUNCTION(vkSetDebugUtilsObjectNameEXT, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
};

#undef AMRSTREAM_VK_FUNCTION

}  // namespace amrstream::vk
