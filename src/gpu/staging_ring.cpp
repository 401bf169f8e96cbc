#include "staging_ring.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace amrstream::gpu {

StagingRing::StagingRing(const vk::Context& ctx, std::size_t slots, VkDeviceSize slotBytes)
    : ctx_(&ctx), slotCount_(slots), slotBytes_(slotBytes) {
  if (slots == 0 || slotBytes == 0)
    throw std::invalid_argument("StagingRing: at least one slot of at least one byte");
  // Buffer creation takes no externally synchronised Vulkan object, so another thread may make
  // them while this one records and submits other work.
  making_ = std::async(std::launch::async, [&ctx, slots, slotBytes] {
    std::vector<vk::Buffer> buffers;
    buffers.reserve(slots);
    for (std::size_t slot = 0; slot < slots; ++slot)
      buffers.push_back(vk::Buffer::readback(ctx, slotBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                             fmt::format("staging slot {}", slot)));
    return buffers;
  });
}

StagingRing::~StagingRing() {
  submissions_.clear();  // waits for pending copies before their buffers go
  if (making_.valid()) making_.wait();
}

void StagingRing::ready() {
  if (!buffers_.empty()) return;
  if (!making_.valid()) throw std::logic_error("StagingRing: making the buffers failed before");
  buffers_ = making_.get();
  submissions_.reserve(slotCount_);
  for (std::size_t slot = 0; slot < slotCount_; ++slot) submissions_.emplace_back(*ctx_);
}

vk::Buffer& StagingRing::buffer(std::size_t slot) {
  ready();
  return buffers_.at(slot);
}

vk::Submission& StagingRing::submission(std::size_t slot) {
  ready();
  return submissions_.at(slot);
}

void StagingRing::waitQuietly() noexcept {
  for (vk::Submission& copy : submissions_) {
    try {
      copy.wait();
    } catch (...) {  // a lost device: nothing left to wait for
    }
  }
}

}  // namespace amrstream::gpu
