#include "vk/vk_error.hpp"

#include <fmt/format.h>

#include <array>
#include <utility>

namespace amrstream::vk {

std::string resultName(VkResult result) {
  switch (result) {
#define AMRSTREAM_RESULT_CASE(name) \
  case name:                        \
    return #name;
    AMRSTREAM_RESULT_CASE(VK_SUCCESS)
    AMRSTREAM_RESULT_CASE(VK_NOT_READY)
    AMRSTREAM_RESULT_CASE(VK_TIMEOUT)
    AMRSTREAM_RESULT_CASE(VK_EVENT_SET)
    AMRSTREAM_RESULT_CASE(VK_EVENT_RESET)
    AMRSTREAM_RESULT_CASE(VK_INCOMPLETE)
    AMRSTREAM_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    AMRSTREAM_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    AMRSTREAM_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    AMRSTREAM_RESULT_CASE(VK_ERROR_DEVICE_LOST)
    AMRSTREAM_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    AMRSTREAM_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    AMRSTREAM_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    AMRSTREAM_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    AMRSTREAM_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    AMRSTREAM_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    AMRSTREAM_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    AMRSTREAM_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
    AMRSTREAM_RESULT_CASE(VK_ERROR_UNKNOWN)
    AMRSTREAM_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    AMRSTREAM_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    AMRSTREAM_RESULT_CASE(VK_ERROR_FRAGMENTATION)
    AMRSTREAM_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    AMRSTREAM_RESULT_CASE(VK_PIPELINE_COMPILE_REQUIRED)
    AMRSTREAM_RESULT_CASE(VK_THREAD_IDLE_KHR)
    AMRSTREAM_RESULT_CASE(VK_THREAD_DONE_KHR)
    AMRSTREAM_RESULT_CASE(VK_OPERATION_DEFERRED_KHR)
    AMRSTREAM_RESULT_CASE(VK_OPERATION_NOT_DEFERRED_KHR)
    AMRSTREAM_RESULT_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef AMRSTREAM_RESULT_CASE
    default:
      return fmt::format("VkResult({})", static_cast<int>(result));
  }
}

std::string formatBytes(uint64_t bytes) {
  static constexpr std::array<const char*, 7> kUnits = {"B",   "KiB", "MiB", "GiB",
                                                        "TiB", "PiB", "EiB"};
  if (bytes < 1024) return fmt::format("{} B", bytes);
  double value = static_cast<double>(bytes);
  size_t unit = 0;
  while (value >= 1024.0 && unit + 1 < kUnits.size()) {
    value /= 1024.0;
    ++unit;
  }
  return fmt::format("{:.1f} {}", value, kUnits[unit]);
}

VulkanError::VulkanError(VkResult result, std::string expression, std::string_view file, int line)
    : std::runtime_error(
          fmt::format("{} failed with {} at {}:{}", expression, resultName(result), file, line)),
      result_(result),
      expression_(std::move(expression)),
      file_(file),
      line_(line) {}

VulkanError::VulkanError(VkResult result, std::string message)
    : std::runtime_error(fmt::format("{} ({})", message, resultName(result))), result_(result) {}

}  // namespace amrstream::vk
