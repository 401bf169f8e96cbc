#include "vk/instance.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <string_view>

#include "vk/context_error.hpp"
#include "vk/device_support.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {
namespace {

bool layerAvailable(std::string_view name) {
  uint32_t count = 0;
  AMRSTREAM_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
  std::vector<VkLayerProperties> layers(count);
  AMRSTREAM_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
  for (const auto& layer : layers) {
    if (name == layer.layerName) return true;
  }
  return false;
}

bool extensionListed(const char* layer, std::string_view name) {
  uint32_t count = 0;
  if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> extensions(count);
  AMRSTREAM_VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()));
  for (const auto& extension : extensions) {
    if (name == extension.extensionName) return true;
  }
  return false;
}

// Offered by the implementation and implicit layers, or by `layer` when one is given.
bool instanceExtensionAvailable(std::string_view name, const char* layer) {
  return extensionListed(nullptr, name) || (layer != nullptr && extensionListed(layer, name));
}

}  // namespace

Instance createInstance(const InstanceOptions& options) {
  uint32_t loaderVersion = VK_API_VERSION_1_0;
  AMRSTREAM_VK_CHECK(vkEnumerateInstanceVersion(&loaderVersion));
  if (loaderVersion < kRequiredApiVersion) {
    throw ContextError(
        fmt::format("the Vulkan loader offers API {}, amrstream needs 1.2: update "
                    "libvulkan1",
                    formatApiVersion(loaderVersion)));
  }
  if (options.validation && !layerAvailable(kValidationLayer)) {
    throw ContextError(
        fmt::format("validation was requested but {} is not installed (Debian: "
                    "apt-get install vulkan-validationlayers)",
                    kValidationLayer));
  }
  const char* layer = options.validation ? kValidationLayer : nullptr;

  Instance instance;
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  for (const std::string& extension : options.extensions) {
    if (!instanceExtensionAvailable(extension, layer)) {
      throw ContextError(fmt::format(
          "the Vulkan loader offers no instance extension {}, which the window system needs "
          "(update libvulkan1 and the driver, or use a headless command)",
          extension));
    }
    extensions.push_back(extension.c_str());
  }
  if (options.validation) layers.push_back(kValidationLayer);
  if ((options.validation || options.debugUtils) &&
      instanceExtensionAvailable(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, layer)) {
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    instance.debugUtilsEnabled = true;
  }

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "amrstream";
  app.pEngineName = "amrstream";
  app.apiVersion = kRequiredApiVersion;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;

  VkDebugUtilsMessengerCreateInfoEXT messenger{};
  VkValidationFeatureEnableEXT syncValidation =
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  if (options.validation) {
    if (options.log == nullptr) throw std::logic_error("createInstance: validation needs a log");
    if (instance.debugUtilsEnabled) {
      messenger = options.log->messengerCreateInfo();
      info.pNext = &messenger;
    }
    if (options.synchronizationValidation &&
        instanceExtensionAvailable(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME, layer)) {
      extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
      features.enabledValidationFeatureCount = 1;
      features.pEnabledValidationFeatures = &syncValidation;
      features.pNext = info.pNext;
      info.pNext = &features;
    }
  }
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();

  VkInstance handle = VK_NULL_HANDLE;
  const VkResult result = vkCreateInstance(&info, nullptr, &handle);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
    throw ContextError(
        "no Vulkan driver found (VK_ERROR_INCOMPATIBLE_DRIVER): install one (Debian: "
        "apt-get install -t bookworm-backports mesa-vulkan-drivers) or check VK_DRIVER_FILES");
  }
  AMRSTREAM_VK_CHECK(result);
  instance.handle = UniqueHandle<VkInstance>(NoOwner{}, handle);
  return instance;
}

std::vector<VkPhysicalDevice> enumeratePhysicalDevices(VkInstance instance) {
  uint32_t count = 0;
  AMRSTREAM_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  AMRSTREAM_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  devices.resize(count);
  return devices;
}

}  // namespace amrstream::vk
