#pragma once
// Moving whole arrays between host and device: a staging buffer plus a one-shot copy, waited on.
// Convenient and synchronous; streaming paths that overlap transfers with work record their own
// copies with the barriers of commands.hpp.

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstring>
#include <ranges>
#include <span>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

#include "vk/buffer.hpp"

namespace amrstream::vk {

class Context;

// A device-local buffer holding `bytes`; TRANSFER_DST is added to `usage`. On return the copy
// has completed and is visible to any later command on the context's queue.
Buffer uploadToDeviceLocal(const Context& ctx, std::span<const std::byte> bytes,
                           VkBufferUsageFlags usage, std::string_view name);

template <std::ranges::contiguous_range Range>
requires std::is_trivially_copyable_v<std::ranges::range_value_t<Range>> Buffer uploadToDeviceLocal(
    const Context& ctx, const Range& data, VkBufferUsageFlags usage, std::string_view name) {
  return uploadToDeviceLocal(
      ctx, std::as_bytes(std::span(std::ranges::data(data), std::ranges::size(data))), usage, name);
}

// The whole of `buffer` (which needs TRANSFER_SRC usage), after all work submitted before.
std::vector<std::byte> readBack(const Context& ctx, const Buffer& buffer);

// readBack as elements of T; throws std::invalid_argument when the size is not a multiple of
// sizeof(T).
template <typename T>
requires std::is_trivially_copyable_v<T> std::vector<T> readBackAs(const Context& ctx,
                                                                   const Buffer& buffer) {
  if (buffer.size() % sizeof(T) != 0) {
    throw std::invalid_argument("readBackAs: buffer size is not a multiple of the element size");
  }
  const std::vector<std::byte> bytes = readBack(ctx, buffer);
  std::vector<T> values(bytes.size() / sizeof(T));
  if (!bytes.empty()) std::memcpy(values.data(), bytes.data(), bytes.size());
  return values;
}

}  // namespace amrstream::vk
