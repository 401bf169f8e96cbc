#include "vk/buffer.hpp"

#include <fmt/format.h>

#include <optional>
#include <utility>

#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {
namespace {

constexpr VkDeviceSize kEmptyBufferSize = 16;

struct MemoryPreference {
  VkMemoryPropertyFlags required = 0;
  VkMemoryPropertyFlags preferred = 0;
  VkMemoryPropertyFlags avoided = 0;
};

MemoryPreference preferenceFor(Buffer::Intent intent) {
  switch (intent) {
    case Buffer::Intent::DeviceLocal:
      // Avoid the small host-visible device heap (BAR) where a plain device-local type exists.
      return {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT};
    case Buffer::Intent::Upload:
      return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0,
              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT};
    case Buffer::Intent::Readback:
      return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, VK_MEMORY_PROPERTY_HOST_CACHED_BIT,
              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT};
  }
  return {};
}

// The first allowed type with the required flags, trying in turn: with the preferred flags and
// none of the avoided ones; with the preferred; without the avoided; with the required alone.
std::optional<uint32_t> findMemoryType(const VkPhysicalDeviceMemoryProperties& memory,
                                       uint32_t allowedTypes, MemoryPreference preference) {
  const MemoryPreference attempts[] = {
      {preference.required | preference.preferred, 0, preference.avoided},
      {preference.required | preference.preferred, 0, 0},
      {preference.required, 0, preference.avoided},
      {preference.required, 0, 0},
  };
  for (const MemoryPreference& attempt : attempts) {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
      const VkMemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
      if ((allowedTypes & (1u << i)) != 0 && (flags & attempt.required) == attempt.required &&
          (flags & attempt.avoided) == 0) {
        return i;
      }
    }
  }
  return std::nullopt;
}

std::string_view intentName(Buffer::Intent intent) {
  switch (intent) {
    case Buffer::Intent::DeviceLocal:
      return "device-local";
    case Buffer::Intent::Upload:
      return "upload";
    case Buffer::Intent::Readback:
      return "readback";
  }
  return "";
}

[[noreturn]] void throwAllocationError(VkResult result, std::string_view name, VkDeviceSize size,
                                       std::string_view detail) {
  const char* what = result == VK_ERROR_OUT_OF_HOST_MEMORY     ? "out of host memory"
                     : result == VK_ERROR_OUT_OF_DEVICE_MEMORY ? "out of device memory"
                                                               : "failed";
  throw VulkanError(result, fmt::format("{} allocating '{}' ({}){}{}", what, name,
                                        formatBytes(size), detail.empty() ? "" : ": ", detail));
}

// The likely reason when the size is beyond maxMemoryAllocationSize; empty otherwise.
std::string limitNote(const Context& ctx, VkDeviceSize size) {
  const VkDeviceSize limit = ctx.maxMemoryAllocationSize();
  if (limit == 0 || size <= limit) return {};
  return fmt::format(
      "; allocations beyond maxMemoryAllocationSize of {} ({}) may fail: split "
      "the data or process it in chunks",
      ctx.deviceName(), formatBytes(limit));
}

}  // namespace

Buffer Buffer::deviceLocal(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                           std::string_view name) {
  return Buffer(ctx, size, usage, name, Intent::DeviceLocal);
}

Buffer Buffer::upload(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                      std::string_view name) {
  return Buffer(ctx, size, usage, name, Intent::Upload);
}

Buffer Buffer::readback(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                        std::string_view name) {
  return Buffer(ctx, size, usage, name, Intent::Readback);
}

Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
               std::string_view name, Intent intent)
    : name_(name), size_(size), usage_(usage), device_(ctx.device()) {
  const bool wantsAddress = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0;
  if (wantsAddress && !ctx.bufferDeviceAddressEnabled()) {
    throw VulkanError(VK_ERROR_FEATURE_NOT_PRESENT,
                      fmt::format("buffer '{}' asks for a device address, but {} has no "
                                  "bufferDeviceAddress feature",
                                  name, ctx.deviceName()));
  }

  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size == 0 ? kEmptyBufferSize : size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  if (const VkResult r = vkCreateBuffer(device_, &info, nullptr, &buffer); r != VK_SUCCESS) {
    throwAllocationError(r, name, size,
                         fmt::format("vkCreateBuffer failed{}", limitNote(ctx, size)));
  }
  buffer_ = UniqueHandle<VkBuffer>(device_, buffer);

  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(device_, buffer, &requirements);
  const auto& memory = ctx.memoryProperties();
  const std::optional<uint32_t> type =
      findMemoryType(memory, requirements.memoryTypeBits, preferenceFor(intent));
  if (!type) {
    throwAllocationError(VK_ERROR_FEATURE_NOT_PRESENT, name, size,
                         fmt::format("{} has no {} memory type for this buffer", ctx.deviceName(),
                                     intentName(intent)));
  }
  // A size beyond the heap is invalid usage (VUID-vkAllocateMemory-pAllocateInfo-01713) rather
  // than a clean VK_ERROR_OUT_OF_DEVICE_MEMORY, so refuse it here. Beyond
  // maxMemoryAllocationSize an allocation may fail but is valid: the driver decides.
  const VkMemoryType& memoryType = memory.memoryTypes[*type];
  const VkDeviceSize heapSize = memory.memoryHeaps[memoryType.heapIndex].size;
  const VkResult tooLarge = (memoryType.propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) != 0
                                ? VK_ERROR_OUT_OF_DEVICE_MEMORY
                                : VK_ERROR_OUT_OF_HOST_MEMORY;
  if (requirements.size > heapSize) {
    throwAllocationError(tooLarge, name, size,
                         fmt::format("larger than the {} memory heap of {}", formatBytes(heapSize),
                                     ctx.deviceName()));
  }

  MemoryLedger& ledger = ctx.memoryLedger();
  std::optional<MemoryCharge> charge = ledger.charge(requirements.size);
  if (!charge) {
    throwAllocationError(tooLarge, name, size,
                         fmt::format("the limit AMRSTREAM_DEVICE_MEMORY_LIMIT of {} would be "
                                     "exceeded ({} in use)",
                                     formatBytes(*ledger.limit()), formatBytes(ledger.used())));
  }
  charge_ = std::move(*charge);

  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocation.pNext = wantsAddress ? &flags : nullptr;
  allocation.allocationSize = requirements.size;
  allocation.memoryTypeIndex = *type;
  VkDeviceMemory deviceMemory = VK_NULL_HANDLE;
  if (const VkResult r = vkAllocateMemory(device_, &allocation, nullptr, &deviceMemory);
      r != VK_SUCCESS) {
    throwAllocationError(r, name, size,
                         fmt::format("vkAllocateMemory failed{}", limitNote(ctx, size)));
  }
  memory_ = UniqueHandle<VkDeviceMemory>(device_, deviceMemory);
  AMRSTREAM_VK_CHECK(vkBindBufferMemory(device_, buffer, deviceMemory, 0));

  if (intent != Intent::DeviceLocal) {
    void* pointer = nullptr;
    AMRSTREAM_VK_CHECK(vkMapMemory(device_, deviceMemory, 0, VK_WHOLE_SIZE, 0, &pointer));
    mapped_ = static_cast<std::byte*>(pointer);
    coherent_ = (memoryType.propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
  }
  if (wantsAddress) {
    VkBufferDeviceAddressInfo addressInfo{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    addressInfo.buffer = buffer;
    address_ = vkGetBufferDeviceAddress(device_, &addressInfo);
  }
  setDebugName(ctx, buffer, name);
  setDebugName(ctx, deviceMemory, name);
}

Buffer::Buffer(Buffer&& other) noexcept
    : name_(std::move(other.name_)),
      size_(std::exchange(other.size_, 0)),
      usage_(std::exchange(other.usage_, 0)),
      device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      coherent_(std::exchange(other.coherent_, true)),
      buffer_(std::move(other.buffer_)),
      charge_(std::move(other.charge_)),
      memory_(std::move(other.memory_)),
      mapped_(std::exchange(other.mapped_, nullptr)),
      address_(std::exchange(other.address_, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    Buffer moved(std::move(other));
    std::swap(name_, moved.name_);
    std::swap(size_, moved.size_);
    std::swap(usage_, moved.usage_);
    std::swap(device_, moved.device_);
    std::swap(coherent_, moved.coherent_);
    std::swap(buffer_, moved.buffer_);
    std::swap(charge_, moved.charge_);
    std::swap(memory_, moved.memory_);
    std::swap(mapped_, moved.mapped_);
    std::swap(address_, moved.address_);
  }
  return *this;
}

void Buffer::invalidateMapped() const {
  if (mapped_ == nullptr || coherent_) return;
  VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
  range.memory = memory_.get();
  range.offset = 0;
  range.size = VK_WHOLE_SIZE;
  AMRSTREAM_VK_CHECK(vkInvalidateMappedMemoryRanges(device_, 1, &range));
}

}  // namespace amrstream::vk
