#pragma once
// The receiving end of a VK_EXT_debug_utils messenger: counts ERROR-severity messages, keeps the
// first few, and prints errors to stderr (warnings too when the environment variable
// AMRSTREAM_VK_VERBOSE is set to anything but "0"). Thread-safe: drivers and layers may call the
// messenger from any thread. Shared (std::shared_ptr) so a test can still read the count after
// the context, and the leak reports of vkDestroyDevice, are gone.

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace amrstream::vk {

class ValidationLog {
 public:
  ValidationLog();
  ValidationLog(const ValidationLog&) = delete;
  ValidationLog& operator=(const ValidationLog&) = delete;

  uint32_t errorCount() const { return errorCount_.load(); }
  // The first kMaxKeptErrors error messages.
  std::vector<std::string> errors() const;

  // A create-info whose callback reports to this log. Chain it into VkInstanceCreateInfo::pNext
  // too, so that vkCreateInstance and vkDestroyInstance are covered.
  VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo();

  static constexpr size_t kMaxKeptErrors = 64;

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                 void* userData);
  void record(VkDebugUtilsMessageSeverityFlagBitsEXT severity, const char* message);

  bool printWarnings_;
  std::atomic<uint32_t> errorCount_{0};
  mutable std::mutex mutex_;
  std::vector<std::string> errors_;
};

}  // namespace amrstream::vk
