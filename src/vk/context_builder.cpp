// ContextBuilder::build(): instance, surface (with presentation), device choice, logical device
// with the features of the requested capabilities, queue and command pool.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "vk/context.hpp"
#include "vk/instance.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {
namespace {

struct Candidate {
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  DeviceSupport support;
  DeviceProperties properties;
  DeviceReport report;
  PresentationSupport presentation;  // probed only with a surface
};

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Empty when `c` can serve; else the device's name and what it lacks.
std::string reasonAgainst(const Candidate& c, CapabilitySet required, bool presenting) {
  std::string reason = describeMissing(c.report, required);
  const std::vector<std::string> missing =
      presenting ? c.presentation.missing() : std::vector<std::string>{};
  if (!missing.empty()) {
    reason += fmt::format("{}cannot present to the window: missing {}",
                          reason.empty() ? c.report.name + ": " : "; ", fmt::join(missing, ", "));
  }
  return reason;
}

std::string listSeen(const std::vector<Candidate>& all) {
  std::string text = "devices seen:";
  for (const Candidate& c : all) text += "\n  " + describeDevice(c.report);
  return text;
}

// `surface` is null for a headless context.
Candidate chooseDevice(VkInstance instance, VkSurfaceKHR surface, CapabilitySet required,
                       const std::optional<uint32_t>& index, const std::optional<std::string>& name,
                       uint32_t slot) {
  const bool presenting = surface != VK_NULL_HANDLE;
  std::vector<Candidate> all;
  const auto devices = enumeratePhysicalDevices(instance);
  for (uint32_t i = 0; i < devices.size(); ++i) {
    Candidate c{devices[i], probeSupport(devices[i]), {}, {}, {}};
    c.properties = queryProperties(devices[i], c.support);
    c.report = makeReport(i, c.support, c.properties);
    if (presenting) c.presentation = probePresentation(devices[i], c.support, surface);
    all.push_back(std::move(c));
  }
  if (all.empty()) {
    throw ContextError(
        "no Vulkan device found: install a driver (Debian: apt-get install -t "
        "bookworm-backports mesa-vulkan-drivers) or check VK_DRIVER_FILES");
  }

  std::vector<const Candidate*> pool;
  if (index) {
    if (*index >= all.size()) {
      throw ContextError(fmt::format("no Vulkan device has index {}; {}", *index, listSeen(all)));
    }
    pool.push_back(&all[*index]);
  } else {
    for (const Candidate& c : all) {
      if (!name || lowercase(c.report.name).find(lowercase(*name)) != std::string::npos) {
        pool.push_back(&c);
      }
    }
    if (pool.empty()) {
      throw ContextError(
          fmt::format("no Vulkan device name contains '{}'; {}", *name, listSeen(all)));
    }
  }

  std::vector<const Candidate*> discrete, qualified;
  for (const Candidate* c : pool) {
    if (!reasonAgainst(*c, required, presenting).empty()) continue;
    qualified.push_back(c);
    if (c->report.type == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU) discrete.push_back(c);
  }
  const std::vector<const Candidate*>& preferred = discrete.empty() ? qualified : discrete;
  const Candidate* chosen = preferred.empty() ? nullptr : preferred[slot % preferred.size()];
  if (chosen == nullptr) {
    if (pool.size() == 1) throw ContextError(reasonAgainst(*pool.front(), required, presenting));
    std::string reasons;
    for (const Candidate* c : pool) reasons += "\n  " + reasonAgainst(*c, required, presenting);
    throw ContextError(fmt::format("no Vulkan device supports {}{}:{}",
                                   required.withImplied().toString(),
                                   presenting ? " and presentation to the window" : "", reasons));
  }
  return *chosen;
}

// The debug messenger that counts the validation layer's errors into `log`.
UniqueHandle<VkDebugUtilsMessengerEXT> createMessenger(VkInstance instance,
                                                       const InstanceFunctions& functions,
                                                       bool debugUtils, ValidationLog& log) {
  if (!debugUtils) {
    throw ContextError(
        "the validation layer offers no VK_EXT_debug_utils, so its errors "
        "could not be counted");
  }
  const VkDebugUtilsMessengerCreateInfoEXT info = log.messengerCreateInfo();
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(
      functions.vkCreateDebugUtilsMessengerEXT(instance, &info, nullptr, &messenger));
  return UniqueHandle<VkDebugUtilsMessengerEXT>(
      {instance, functions.vkDestroyDebugUtilsMessengerEXT.get()}, messenger);
}

UniqueHandle<VkSurfaceKHR> createSurface(const PresentationRequest& presentation,
                                         VkInstance instance) {
  const VkSurfaceKHR surface = presentation.createSurface(instance);
  if (surface == VK_NULL_HANDLE) throw ContextError("the window system gave no Vulkan surface");
  return UniqueHandle<VkSurfaceKHR>(instance, surface);
}

// Acceleration structures cannot even be sized unless rayQuery or rayTracingPipeline is
// enabled (VUID-vkGetAccelerationStructureBuildSizesKHR-rayTracingPipeline-03617), so a
// request for them alone enables whichever of the two the device has.
void addAccelerationStructureSizing(CapabilitySet& capabilities, const DeviceReport& report) {
  if (capabilities.contains(Capability::AccelerationStructure) &&
      !capabilities.contains(Capability::RayQuery) &&
      !capabilities.contains(Capability::RayTracingPipeline)) {
    capabilities.insert(report.status(Capability::RayQuery).supported()
                            ? Capability::RayQuery
                            : Capability::RayTracingPipeline);
  }
}

// The device extensions of `capabilities`, plus VK_KHR_swapchain when presenting.
std::vector<const char*> deviceExtensions(CapabilitySet capabilities, bool presenting) {
  std::vector<const char*> extensions;
  for (Capability c : kAllCapabilities) {
    if (!capabilities.contains(c)) continue;
    for (const char* extension : requirementsOf(c).extensions) extensions.push_back(extension);
  }
  if (presenting) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  return extensions;
}

// The logical device with the features of `capabilities` and one queue of `queueFamilyIndex`.
UniqueHandle<VkDevice> createDevice(VkPhysicalDevice physicalDevice, uint32_t queueFamilyIndex,
                                    CapabilitySet capabilities, bool presenting, bool shaderInt64,
                                    bool bufferDeviceAddress) {
  const std::vector<const char*> extensions = deviceExtensions(capabilities, presenting);

  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.features.shaderInt64 = shaderInt64 ? VK_TRUE : VK_FALSE;
  VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  vulkan12.scalarBlockLayout = VK_TRUE;
  vulkan12.bufferDeviceAddress = bufferDeviceAddress ? VK_TRUE : VK_FALSE;
  VkPhysicalDeviceAccelerationStructureFeaturesKHR accel{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  accel.accelerationStructure = VK_TRUE;
  VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  rayQuery.rayQuery = VK_TRUE;
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  pipeline.rayTracingPipeline = VK_TRUE;

  void** next = &features.pNext;
  auto chain = [&next](auto& s) {
    *next = &s;
    next = &s.pNext;
  };
  chain(vulkan12);
  if (capabilities.contains(Capability::AccelerationStructure)) chain(accel);
  if (capabilities.contains(Capability::RayQuery)) chain(rayQuery);
  if (capabilities.contains(Capability::RayTracingPipeline)) chain(pipeline);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamilyIndex;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.pNext = &features;
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  deviceInfo.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  deviceInfo.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateDevice(physicalDevice, &deviceInfo, nullptr, &device));
  return UniqueHandle<VkDevice>(NoOwner{}, device);
}

UniqueHandle<VkCommandPool> createCommandPool(VkDevice device, uint32_t queueFamilyIndex) {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags =
      VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = queueFamilyIndex;
  VkCommandPool pool = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
  return UniqueHandle<VkCommandPool>(device, pool);
}

}  // namespace

Context ContextBuilder::build() const {
  Context ctx;
  const bool validation = validation_ || synchronizationValidation_;
  if (validation) ctx.validationLog_ = std::make_shared<ValidationLog>();
  ctx.memoryLedger_ = std::make_shared<MemoryLedger>(MemoryLedger::limitFromEnvironment());

  Instance instance = createInstance(
      {validation, synchronizationValidation_, validation || debugNames_, ctx.validationLog_.get(),
       presentation_ ? presentation_->instanceExtensions : std::vector<std::string>{}});
  ctx.instance_ = std::move(instance.handle);
  ctx.debugUtils_ = instance.debugUtilsEnabled;
  ctx.instanceFunctions_ = InstanceFunctions::load(ctx.instance(), ctx.debugUtils_);
  if (validation) {
    ctx.messenger_ = createMessenger(ctx.instance(), ctx.instanceFunctions_, ctx.debugUtils_,
                                     *ctx.validationLog_);
  }

  if (presentation_) ctx.surface_ = createSurface(*presentation_, ctx.instance());

  CapabilitySet capabilities = required_.withImplied();
  Candidate chosen = chooseDevice(ctx.instance(), ctx.surface(), capabilities, deviceIndex_,
                                  deviceName_, deviceSlot_);
  addAccelerationStructureSizing(capabilities, chosen.report);
  ctx.physicalDevice_ = chosen.physicalDevice;
  ctx.report_ = std::move(chosen.report);
  ctx.properties_ = chosen.properties;
  ctx.capabilities_ = capabilities;
  ctx.shaderInt64_ = chosen.support.shaderInt64;
  ctx.bufferDeviceAddress_ = chosen.support.bufferDeviceAddress;
  ctx.queueFamilyIndex_ =
      presentation_ ? *chosen.presentation.queueFamily : *chosen.support.computeQueueFamily;
  if (!capabilities.contains(Capability::AccelerationStructure)) {
    ctx.properties_.accelerationStructure = {};
  }
  if (!capabilities.contains(Capability::RayTracingPipeline)) {
    ctx.properties_.rayTracingPipeline = {};
  }

  ctx.device_ = createDevice(ctx.physicalDevice_, ctx.queueFamilyIndex_, capabilities,
                             presentation_.has_value(), ctx.shaderInt64_, ctx.bufferDeviceAddress_);
  ctx.functions_ =
      DeviceFunctions::load(ctx.device(), capabilities.contains(Capability::AccelerationStructure),
                            capabilities.contains(Capability::RayTracingPipeline));
  vkGetDeviceQueue(ctx.device(), ctx.queueFamilyIndex_, 0, &ctx.queue_);
  ctx.pipelineCache_ =
      std::make_unique<PipelineCache>(ctx.device(), ctx.properties(), pipelineCacheDirectory_);

  ctx.commandPool_ = createCommandPool(ctx.device(), ctx.queueFamilyIndex_);
  return ctx;
}

}  // namespace amrstream::vk
