#pragma once
// DeviceUploader: fills device-local buffers through two pinned staging buffers of a few
// megabytes, one filled by the host while the other's copy runs. A whole-array staging buffer
// would double the host memory of the upload and cost about 0.3 s per GiB to make; these are
// made once for all the arrays of a volume. Contents can be generated slot by slot while they
// are written to the staging buffer, so a converted copy of an array (the values padded to
// 16 bytes, say) never exists whole on the host.

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string_view>

#include "util/parallel_copy.hpp"
#include "vk/buffer.hpp"
#include "vk/submission.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::gpu {

class DeviceUploader {
 public:
  static constexpr VkDeviceSize kDefaultChunkBytes = VkDeviceSize(32) << 20;

  // The context must outlive the uploader.
  explicit DeviceUploader(const vk::Context& ctx, VkDeviceSize chunkBytes = kDefaultChunkBytes);
  ~DeviceUploader();

  // Writes elements [first, first + out.size()) of the contents.
  template <typename T>
  using Fill = std::function<void(std::size_t first, std::span<T> out)>;

  // A device-local buffer of `count` elements (TRANSFER_DST added to `usage`) holding what
  // `fill` writes, called for consecutive ranges; complete and visible to later commands on
  // return.
  template <typename T>
  vk::Buffer upload(std::size_t count, VkBufferUsageFlags usage, std::string_view name,
                    const Fill<T>& fill) {
    return uploadBytes(
        count * sizeof(T), sizeof(T), usage, name,
        [&](VkDeviceSize offset, std::span<std::byte> out) {
          fill(offset / sizeof(T), {reinterpret_cast<T*>(out.data()), out.size() / sizeof(T)});
        });
  }
  // The same for an array already on the host.
  template <typename T>
  vk::Buffer upload(std::span<const T> data, VkBufferUsageFlags usage, std::string_view name) {
    return upload<T>(data.size(), usage, name, [&](std::size_t first, std::span<T> out) {
      copyParallel(std::as_bytes(data.subspan(first, out.size())), std::as_writable_bytes(out));
    });
  }

 private:
  using ByteFill = std::function<void(VkDeviceSize offset, std::span<std::byte> out)>;
  vk::Buffer uploadBytes(VkDeviceSize bytes, VkDeviceSize elementBytes, VkBufferUsageFlags usage,
                         std::string_view name, const ByteFill& fill);

  const vk::Context* ctx_;
  VkDeviceSize chunkBytes_;
  vk::Buffer staging_[2];
  std::optional<vk::Submission> copies_[2];  // declared after the buffers: destroyed first
};

}  // namespace amrstream::gpu
