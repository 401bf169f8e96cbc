#pragma once
// The arrays a round brings back from the device, in the order they lie wherever a round's
// points are kept together (a staging slot, or a kept round's buffer): for `count` points,
// array i starts at byte offset_i * count, where offset_i is the bytes per point of the arrays
// before it.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "round_buffers.hpp"
#include "vk/buffer.hpp"

namespace amrstream::gpu {

struct StagedArray {
  const vk::Buffer* source;  // the round's dense array on the device
  std::uint64_t bytesPerPoint;
  std::uint64_t offset;  // the bytes per point of the arrays before it
};

// A round's points left on the device: one buffer per array of its StagedLayout, each holding
// the round's `points` values.
struct KeptRound {
  std::uint64_t points = 0;
  std::vector<vk::Buffer> arrays;
};

class StagedLayout {
 public:
  // Which array holds what.
  static constexpr std::size_t kCells = 0, kTimes = 1, kVectors = 2, kChannels = 3;

  StagedLayout(const RoundBuffers& b, std::size_t channels, bool vorticity) {
    add(b.densePositions, sizeof(glm::vec3));
    add(b.denseTimes, sizeof(float));
    add(b.denseVectors, sizeof(glm::vec3));
    add(b.channels, channels * sizeof(float));
    vorticity_ = vorticity ? add(b.vorticity, sizeof(glm::vec3)) : kNone;
    regionIds_ = b.withRegionIds ? add(b.denseRegionIds, sizeof(std::int32_t)) : kNone;
    if (vorticity_ == kNone) vorticity_ = arrays_.size();
    if (regionIds_ == kNone) regionIds_ = arrays_.size();
  }
  std::uint64_t bytesPerPoint() const { return bytesPerPoint_; }
  std::span<const StagedArray> arrays() const { return arrays_; }
  // The vorticity's and the region ids' arrays; arrays().size() when there are none.
  std::size_t vorticity() const { return vorticity_; }
  std::size_t regionIds() const { return regionIds_; }
  // Where array `index` of `count` points starts in `bytes`.
  template <typename T>
  const T* in(std::span<const std::byte> bytes, std::size_t index, std::size_t count) const {
    return reinterpret_cast<const T*>(bytes.data() + arrays_[index].offset * count);
  }

 private:
  static constexpr std::size_t kNone = ~std::size_t(0);
  std::size_t add(const vk::Buffer& source, std::uint64_t bytes) {
    arrays_.push_back({&source, bytes, bytesPerPoint_});
    bytesPerPoint_ += bytes;
    return arrays_.size() - 1;
  }
  std::vector<StagedArray> arrays_;
  std::uint64_t bytesPerPoint_ = 0;
  std::size_t vorticity_ = 0, regionIds_ = 0;
};

}  // namespace amrstream::gpu
