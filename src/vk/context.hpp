#pragma once
// Context: one Vulkan device ready for compute and, as requested, acceleration structures, ray
// queries, ray tracing pipelines and presentation to a window. It owns, in creation (and reverse
// destruction) order: the validation log, the instance, the debug messenger, the window surface
// (with presentation only), the logical device, one queue and a command pool on it. The queue is
// compute-capable; with presentation it also does graphics and presents to the surface, so the
// tracer, the renderer and the presenter share it. Move-only. Not thread-safe: the command pool
// and the queue are for one thread at a time.
//
// ContextBuilder chooses the device and returns a Context or throws ContextError with a readable
// reason (which device lacks what, and what to do about it).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vk/capability.hpp"
#include "vk/context_error.hpp"
#include "vk/device_functions.hpp"
#include "vk/device_report.hpp"
#include "vk/device_support.hpp"
#include "vk/memory_ledger.hpp"
#include "vk/pipeline_cache.hpp"
#include "vk/presentation.hpp"
#include "vk/unique_handle.hpp"
#include "vk/validation_log.hpp"

namespace amrstream::vk {

class Context {
 public:
  Context(Context&&) noexcept = default;
  Context& operator=(Context&&) noexcept = default;
  ~Context();

  VkInstance instance() const { return instance_.get(); }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkDevice device() const { return device_.get(); }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamilyIndex() const { return queueFamilyIndex_; }
  VkCommandPool commandPool() const { return commandPool_.get(); }
  const DeviceFunctions& functions() const { return functions_; }
  const InstanceFunctions& instanceFunctions() const { return instanceFunctions_; }

  const DeviceReport& report() const { return report_; }
  const std::string& deviceName() const { return report_.name; }
  const VkPhysicalDeviceProperties& properties() const { return properties_.core; }
  const VkPhysicalDeviceLimits& limits() const { return properties_.core.limits; }
  // Zero unless the context has Capability::AccelerationStructure.
  const VkPhysicalDeviceAccelerationStructurePropertiesKHR& accelerationStructureProperties()
      const {
    return properties_.accelerationStructure;
  }
  // Zero unless the context has Capability::RayTracingPipeline.
  const VkPhysicalDeviceRayTracingPipelinePropertiesKHR& rayTracingPipelineProperties() const {
    return properties_.rayTracingPipeline;
  }
  const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return properties_.memory; }
  std::vector<VkDeviceSize> memoryHeapSizes() const;
  VkDeviceSize maxMemoryAllocationSize() const { return properties_.maxMemoryAllocationSize; }
  // Every pipeline is created through this cache, which keeps compiled kernels on disk.
  VkPipelineCache pipelineCache() const { return pipelineCache_->handle(); }
  const PipelineCache& pipelineCacheFile() const { return *pipelineCache_; }
  // Every buffer's memory is charged here (see memory_ledger.hpp for the optional limit).
  MemoryLedger& memoryLedger() const { return *memoryLedger_; }

  // The requested capabilities plus those they imply (see Capability::AccelerationStructure).
  CapabilitySet capabilities() const { return capabilities_; }
  bool has(Capability capability) const { return capabilities_.contains(capability); }
  bool bufferDeviceAddressEnabled() const { return bufferDeviceAddress_; }
  bool debugUtilsEnabled() const { return debugUtils_; }
  bool validationEnabled() const { return validationLog_ != nullptr; }
  // With presentation: the window's surface and VK_KHR_swapchain enabled. Null when headless.
  VkSurfaceKHR surface() const { return surface_.get(); }
  bool presentationEnabled() const { return static_cast<bool>(surface_); }

  // ERROR-severity messages from the validation layer and the loader so far; 0 without
  // validation.
  uint32_t validationErrorCount() const;
  // Null without validation. Outlives the context, so the messages of its destruction count.
  std::shared_ptr<const ValidationLog> validationLog() const { return validationLog_; }

 private:
  friend class ContextBuilder;
  Context() = default;

  std::shared_ptr<ValidationLog> validationLog_;
  std::shared_ptr<MemoryLedger> memoryLedger_;
  UniqueHandle<VkInstance> instance_;
  InstanceFunctions instanceFunctions_;
  UniqueHandle<VkDebugUtilsMessengerEXT> messenger_;
  UniqueHandle<VkSurfaceKHR> surface_;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  DeviceReport report_;
  DeviceProperties properties_;
  CapabilitySet capabilities_;
  bool shaderInt64_ = false;
  bool bufferDeviceAddress_ = false;
  bool debugUtils_ = false;
  UniqueHandle<VkDevice> device_;
  std::unique_ptr<PipelineCache> pipelineCache_;
  DeviceFunctions functions_;
  uint32_t queueFamilyIndex_ = 0;
  VkQueue queue_ = VK_NULL_HANDLE;
  UniqueHandle<VkCommandPool> commandPool_;
};

class ContextBuilder {
 public:
  ContextBuilder& require(Capability capability);
  ContextBuilder& require(CapabilitySet capabilities);
  // Use the device at this index of vkEnumeratePhysicalDevices (see listDevices()).
  ContextBuilder& deviceIndex(uint32_t index);
  // Use the first device whose name contains `substring` (case-insensitive) and can serve.
  ContextBuilder& deviceName(std::string substring);
  // Among the devices that qualify (the discrete GPUs if any qualifies, else all), take the one
  // at `slot` modulo their count instead of the first: ranks of one host pass their local rank
  // to spread over its GPUs. 0 by default.
  ContextBuilder& deviceSlot(uint32_t slot);
  // VK_LAYER_KHRONOS_validation plus a messenger that counts errors. Off by default.
  ContextBuilder& validation(bool enabled);
  // The layer's synchronization validation as well (slower); implies validation.
  ContextBuilder& synchronizationValidation(bool enabled);
  // Object names for debuggers (RenderDoc, Nsight) without validation; on with validation.
  ContextBuilder& debugNames(bool enabled);
  // Where the pipeline cache's file lies (none: in memory only); by default
  // cacheDirectoryFromEnvironment().
  ContextBuilder& pipelineCacheDirectory(std::optional<std::filesystem::path> directory);
  // Presentation to a window: `instanceExtensions` are enabled on the instance (throws
  // ContextError at build() when the loader lacks one), `createSurface` is called once with the
  // new instance and the context takes the surface. Only devices with VK_KHR_swapchain and a
  // queue family doing graphics, compute and presentation to that surface qualify. Off by
  // default: a context without it is headless.
  ContextBuilder& presentation(std::vector<std::string> instanceExtensions,
                               SurfaceFactory createSurface);

  // Without a device filter: the first discrete GPU that supports the requirements, else the
  // first device that does. Throws ContextError when no device qualifies, listing each device
  // seen and what it lacks; VulkanError when a Vulkan call fails.
  Context build() const;

 private:
  CapabilitySet required_{Capability::Compute};
  std::optional<uint32_t> deviceIndex_;
  std::optional<std::string> deviceName_;
  uint32_t deviceSlot_ = 0;
  bool validation_ = false;
  bool synchronizationValidation_ = false;
  bool debugNames_ = false;
  std::optional<std::filesystem::path> pipelineCacheDirectory_ = cacheDirectoryFromEnvironment();
  std::optional<PresentationRequest> presentation_;
};

}  // namespace amrstream::vk
