#include "vk/context.hpp"

#include <utility>

namespace amrstream::vk {

Context::~Context() {
  // Objects may still be in use by the queue when the last owner lets go; the members below are
  // destroyed after this body, and destroying them while in use is invalid.
  if (device_) vkDeviceWaitIdle(device_.get());
}

std::vector<VkDeviceSize> Context::memoryHeapSizes() const {
  std::vector<VkDeviceSize> sizes;
  for (uint32_t i = 0; i < properties_.memory.memoryHeapCount; ++i) {
    sizes.push_back(properties_.memory.memoryHeaps[i].size);
  }
  return sizes;
}

uint32_t Context::validationErrorCount() const {
  return validationLog_ ? validationLog_->errorCount() : 0;
}

ContextBuilder& ContextBuilder::require(Capability capability) {
  required_.insert(capability);
  return *this;
}

ContextBuilder& ContextBuilder::require(CapabilitySet capabilities) {
  required_.insert(capabilities);
  return *this;
}

ContextBuilder& ContextBuilder::deviceIndex(uint32_t index) {
  deviceIndex_ = index;
  return *this;
}

ContextBuilder& ContextBuilder::deviceName(std::string substring) {
  deviceName_ = std::move(substring);
  return *this;
}

ContextBuilder& ContextBuilder::deviceSlot(uint32_t slot) {
  deviceSlot_ = slot;
  return *this;
}

ContextBuilder& ContextBuilder::validation(bool enabled) {
  validation_ = enabled;
  return *this;
}

ContextBuilder& ContextBuilder::synchronizationValidation(bool enabled) {
  synchronizationValidation_ = enabled;
  return *this;
}

ContextBuilder& ContextBuilder::debugNames(bool enabled) {
  debugNames_ = enabled;
  return *this;
}

ContextBuilder& ContextBuilder::pipelineCacheDirectory(
    std::optional<std::filesystem::path> directory) {
  pipelineCacheDirectory_ = std::move(directory);
  return *this;
}

ContextBuilder& ContextBuilder::presentation(std::vector<std::string> instanceExtensions,
                                             SurfaceFactory createSurface) {
  presentation_ = PresentationRequest{std::move(instanceExtensions), std::move(createSurface)};
  return *this;
}

}  // namespace amrstream::vk
