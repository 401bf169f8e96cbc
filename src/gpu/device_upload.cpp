#include "device_upload.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "vk/commands.hpp"

namespace amrstream::gpu {

DeviceUploader::DeviceUploader(const vk::Context& ctx, VkDeviceSize chunkBytes)
    : ctx_(&ctx), chunkBytes_(chunkBytes) {
  if (chunkBytes == 0) throw std::invalid_argument("DeviceUploader: chunks of at least one byte");
}

DeviceUploader::~DeviceUploader() {
  for (std::optional<vk::Submission>& copy : copies_) copy.reset();  // waits for pending copies
}

vk::Buffer DeviceUploader::uploadBytes(VkDeviceSize bytes, VkDeviceSize elementBytes,
                                       VkBufferUsageFlags usage, std::string_view name,
                                       const ByteFill& fill) {
  vk::Buffer target =
      vk::Buffer::deviceLocal(*ctx_, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, name);
  if (bytes == 0) return target;
  // Whole elements per chunk, so that a fill writes whole elements.
  const VkDeviceSize chunk = std::max(elementBytes, chunkBytes_ / elementBytes * elementBytes);
  for (int slot = 0; slot < 2; ++slot) {
    const VkDeviceSize wanted = std::min(chunk, bytes);
    if (staging_[slot].size() >= wanted) continue;
    if (copies_[slot]) copies_[slot]->wait();
    staging_[slot] = vk::Buffer::upload(*ctx_, std::max(wanted, staging_[slot].size()),
                                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                        fmt::format("upload staging {}", slot));
    if (!copies_[slot]) copies_[slot].emplace(*ctx_);
  }
  int slot = 0;
  for (VkDeviceSize offset = 0; offset < bytes; offset += chunk, slot ^= 1) {
    const VkDeviceSize n = std::min(chunk, bytes - offset);
    copies_[slot]->wait();  // the slot's previous copy has read it
    // Coherent memory: host writes before vkQueueSubmit are visible to the device.
    fill(offset, staging_[slot].mapped().first(n));
    copies_[slot]->submit([&](VkCommandBuffer cmd) {
      const VkBufferCopy region{0, offset, n};
      vkCmdCopyBuffer(cmd, staging_[slot].handle(), target.handle(), 1, &region);
      vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kAny);
    });
  }
  for (std::optional<vk::Submission>& copy : copies_) copy->wait();
  return target;
}

}  // namespace amrstream::gpu
