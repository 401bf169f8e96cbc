#include "vk/buffer_transfer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

Buffer uploadToDeviceLocal(const Context& ctx, std::span<const std::byte> bytes,
                           VkBufferUsageFlags usage, std::string_view name) {
  Buffer target =
      Buffer::deviceLocal(ctx, bytes.size(), usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, name);
  if (bytes.empty()) return target;

  Buffer staging = Buffer::upload(ctx, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  fmt::format("{} (staging)", name));
  // Coherent memory: host writes made before vkQueueSubmit are visible to the device without a
  // flush or a barrier (the submission's implicit host-write guarantee).
  std::copy(bytes.begin(), bytes.end(), staging.mapped().begin());
  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, bytes.size()};
    vkCmdCopyBuffer(cmd, staging.handle(), target.handle(), 1, &region);
    // Later submissions are not ordered against this one's memory writes by the fence alone.
    memoryBarrier(cmd, access::kTransferWrite, access::kAny);
  });
  return target;
}

std::vector<std::byte> readBack(const Context& ctx, const Buffer& buffer) {
  if ((buffer.usage() & VK_BUFFER_USAGE_TRANSFER_SRC_BIT) == 0) {
    throw VulkanError(VK_ERROR_FEATURE_NOT_PRESENT,
                      fmt::format("cannot read back '{}': it was created without "
                                  "VK_BUFFER_USAGE_TRANSFER_SRC_BIT",
                                  buffer.name()));
  }
  if (buffer.size() == 0) return {};

  const Buffer staging = Buffer::readback(ctx, buffer.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          fmt::format("{} (readback)", buffer.name()));
  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    memoryBarrier(cmd, access::kAnyWrite, access::kTransferRead);
    const VkBufferCopy region{0, 0, buffer.size()};
    vkCmdCopyBuffer(cmd, buffer.handle(), staging.handle(), 1, &region);
    // The fence does not make device writes visible to the host; this barrier does.
    memoryBarrier(cmd, access::kTransferWrite, access::kHostRead);
  });
  staging.invalidateMapped();
  const auto bytes = staging.mapped();
  return {bytes.begin(), bytes.end()};
}

}  // namespace amrstream::vk
