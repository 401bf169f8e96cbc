#include "vk/validation_log.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace amrstream::vk {

ValidationLog::ValidationLog() {
  const char* verbose = std::getenv("AMRSTREAM_VK_VERBOSE");
  printWarnings_ = verbose != nullptr && *verbose != '\0' && std::string_view(verbose) != "0";
}

std::vector<std::string> ValidationLog::errors() const {
  std::lock_guard lock(mutex_);
  return errors_;
}

VkDebugUtilsMessengerCreateInfoEXT ValidationLog::messengerCreateInfo() {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = &ValidationLog::callback;
  info.pUserData = this;
  return info;
}

VkBool32 ValidationLog::callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                 VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData) {
  static_cast<ValidationLog*>(userData)->record(severity, data->pMessage);
  // VK_FALSE: the call that triggered the message goes on (the specification reserves VK_TRUE
  // for layer development).
  return VK_FALSE;
}

void ValidationLog::record(VkDebugUtilsMessageSeverityFlagBitsEXT severity, const char* message) {
  const std::string_view text = message != nullptr ? message : "(no message)";
  if ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0) {
    ++errorCount_;
    std::lock_guard lock(mutex_);
    if (errors_.size() < kMaxKeptErrors) errors_.emplace_back(text);
    fmt::print(stderr, "[vulkan error] {}\n", text);
  } else if ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) != 0) {
    if (printWarnings_) {
      std::lock_guard lock(mutex_);
      fmt::print(stderr, "[vulkan warning] {}\n", text);
    }
  }
}

}  // namespace amrstream::vk
