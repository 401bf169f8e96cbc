#include "vk/memory_ledger.hpp"

#include <cstdlib>
#include <stdexcept>

namespace amrstream::vk {

MemoryCharge& MemoryCharge::operator=(MemoryCharge&& other) noexcept {
  if (this != &other) {
    if (ledger_) ledger_->release(bytes_);
    ledger_ = std::move(other.ledger_);
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

MemoryCharge::~MemoryCharge() {
  if (ledger_) ledger_->release(bytes_);
}

std::optional<VkDeviceSize> MemoryLedger::limitFromEnvironment() {
  const char* text = std::getenv("AMRSTREAM_DEVICE_MEMORY_LIMIT");
  if (!text || !*text) return std::nullopt;
  const std::string value(text);
  std::size_t digits = 0;
  while (digits < value.size() && value[digits] >= '0' && value[digits] <= '9') ++digits;
  const std::string suffix = value.substr(digits);
  const int shift = suffix.empty()  ? 0
                    : suffix == "K" ? 10
                    : suffix == "M" ? 20
                    : suffix == "G" ? 30
                                    : -1;
  if (digits == 0 || digits > 12 || shift < 0)
    throw std::invalid_argument("AMRSTREAM_DEVICE_MEMORY_LIMIT='" + value +
                                "' is not a size (bytes, or a number with K, M or G)");
  return VkDeviceSize(std::stoull(value.substr(0, digits))) << shift;
}

std::optional<MemoryCharge> MemoryLedger::charge(VkDeviceSize bytes) {
  VkDeviceSize used = used_.load();
  do {
    if (limit_ && (bytes > *limit_ || used > *limit_ - bytes)) return std::nullopt;
  } while (!used_.compare_exchange_weak(used, used + bytes));
  return MemoryCharge(shared_from_this(), bytes);
}

}  // namespace amrstream::vk
