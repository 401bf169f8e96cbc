#pragma once
// A few pinned host buffers that the output of a round passes through on its way to the host,
// piece by piece: while the host unpacks one piece, the device copies the next ones into the
// other slots. Pinned memory stays the same few megabytes however large the rounds are (making
// pinned memory is slow, a few GB/s), and the copies overlap the unpacking instead of
// preceding it.
//
// The buffers are made on another thread from the constructor on, so that making them overlaps
// the caller's other setup; the first use waits for them.

#include <cstddef>
#include <future>
#include <vector>

#include "vk/buffer.hpp"
#include "vk/submission.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::gpu {

class StagingRing {
 public:
  static constexpr std::size_t kDefaultSlots = 4;
  static constexpr VkDeviceSize kDefaultSlotBytes = VkDeviceSize(16) << 20;

  // The context must outlive the ring. Throws std::invalid_argument for no slots or 0 bytes.
  StagingRing(const vk::Context& ctx, std::size_t slots = kDefaultSlots,
              VkDeviceSize slotBytes = kDefaultSlotBytes);
  StagingRing(StagingRing&&) = delete;
  ~StagingRing();

  std::size_t slots() const { return slotCount_; }
  VkDeviceSize slotBytes() const { return slotBytes_; }
  std::size_t hostBytes() const { return slotCount_ * slotBytes_; }

  // The slot's buffer (transfer destination, host-visible, mapped) and its submission; waits
  // for the buffers the first time, and rethrows what making them threw.
  vk::Buffer& buffer(std::size_t slot);
  vk::Submission& submission(std::size_t slot);
  // Waits for every slot's pending copy, ignoring a lost device (for destructors).
  void waitQuietly() noexcept;

 private:
  void ready();

  const vk::Context* ctx_;
  std::size_t slotCount_;
  VkDeviceSize slotBytes_;
  std::future<std::vector<vk::Buffer>> making_;
  std::vector<vk::Buffer> buffers_;
  std::vector<vk::Submission> submissions_;  // made with the first use, on the caller's thread
};

}  // namespace amrstream::gpu
