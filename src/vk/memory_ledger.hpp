#pragma once
// An optional cap on the device memory one context allocates, for sharing a GPU with other
// work and for rehearsing "out of device memory" on any device: AMRSTREAM_DEVICE_MEMORY_LIMIT
// (bytes, or with a K, M or G suffix) makes every allocation beyond it fail as the driver's
// VK_ERROR_OUT_OF_DEVICE_MEMORY would. Without the variable nothing is limited.

#include <vulkan/vulkan.h>

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace amrstream::vk {

class MemoryLedger;

// Bytes held against a ledger, released when destroyed. Move-only.
class MemoryCharge {
 public:
  MemoryCharge() = default;
  MemoryCharge(std::shared_ptr<MemoryLedger> ledger, VkDeviceSize bytes)
      : ledger_(std::move(ledger)), bytes_(bytes) {}
  MemoryCharge(MemoryCharge&& other) noexcept
      : ledger_(std::move(other.ledger_)), bytes_(std::exchange(other.bytes_, 0)) {}
  MemoryCharge& operator=(MemoryCharge&& other) noexcept;
  MemoryCharge(const MemoryCharge&) = delete;
  MemoryCharge& operator=(const MemoryCharge&) = delete;
  ~MemoryCharge();

 private:
  std::shared_ptr<MemoryLedger> ledger_;
  VkDeviceSize bytes_ = 0;
};

class MemoryLedger : public std::enable_shared_from_this<MemoryLedger> {
 public:
  explicit MemoryLedger(std::optional<VkDeviceSize> limit) : limit_(limit) {}

  // The limit from AMRSTREAM_DEVICE_MEMORY_LIMIT; std::invalid_argument naming the variable
  // when its value is not a size.
  static std::optional<VkDeviceSize> limitFromEnvironment();

  // A charge of `bytes`, or nothing when it would take the total past the limit.
  std::optional<MemoryCharge> charge(VkDeviceSize bytes);
  void release(VkDeviceSize bytes) { used_ -= bytes; }

  std::optional<VkDeviceSize> limit() const { return limit_; }
  VkDeviceSize used() const { return used_.load(); }

 private:
  std::optional<VkDeviceSize> limit_;
  std::atomic<VkDeviceSize> used_{0};
};

}  // namespace amrstream::vk
