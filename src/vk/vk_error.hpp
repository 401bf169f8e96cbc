#pragma once
// Errors from Vulkan calls. AMRSTREAM_VK_CHECK throws a VulkanError for every result other than
// VK_SUCCESS (including the positive codes VK_INCOMPLETE, VK_TIMEOUT, VK_NOT_READY), so a caller
// that expects one of those must test the result itself. Library code never exits.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace amrstream::vk {

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" for VK_ERROR_OUT_OF_DEVICE_MEMORY; the number for unknown codes.
std::string resultName(VkResult result);

// "12.3 GiB", "512 B": for messages about sizes.
std::string formatBytes(uint64_t bytes);

class VulkanError : public std::runtime_error {
 public:
  // what(): "<expression> failed with <result name> at <file>:<line>".
  VulkanError(VkResult result, std::string expression, std::string_view file, int line);
  // what(): "<message> (<result name>)", for failures that need a sentence of their own, such as
  // "out of device memory allocating 'positions' (12.3 GiB)".
  VulkanError(VkResult result, std::string message);

  VkResult result() const { return result_; }
  const std::string& expression() const { return expression_; }
  // Empty and 0 when the error was raised with a message rather than by AMRSTREAM_VK_CHECK.
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  VkResult result_;
  std::string expression_;
  std::string file_;
  int line_ = 0;
};

}  // namespace amrstream::vk

#define AMRSTREAM_VK_CHECK(expr)                                                         \
  do {                                                                                   \
    const VkResult amrstreamVkResult_ = (expr);                                          \
    if (amrstreamVkResult_ != VK_SUCCESS) {                                              \
      throw ::amrstream::vk::VulkanError(amrstreamVkResult_, #expr, __FILE__, __LINE__); \
    }                                                                                    \
  } while (false)
