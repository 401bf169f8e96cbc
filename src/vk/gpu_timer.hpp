#pragma once
// GpuTimer: device time between two points of one command buffer, from timestamp queries.
//
//   GpuTimer timer(ctx);
//   submitAndWait(ctx, [&](VkCommandBuffer cmd) { timer.start(cmd); ...; timer.stop(cmd); });
//   std::optional<double> s = timer.seconds();
//
// Devices whose compute queue has no timestamps (timestampValidBits 0) give no time: seconds()
// returns nullopt. The context must outlive the timer.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

class GpuTimer {
 public:
  explicit GpuTimer(const Context& ctx);

  bool supported() const { return pool_.get() != VK_NULL_HANDLE; }
  // Resets the queries and writes the first timestamp once all earlier commands are done.
  void start(VkCommandBuffer cmd) const;
  // Writes the second timestamp once all earlier commands are done.
  void stop(VkCommandBuffer cmd) const;
  // Seconds between start and stop, after the command buffer has completed.
  std::optional<double> seconds() const;

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  UniqueHandle<VkQueryPool> pool_;
  double secondsPerTick_ = 0.0;
  std::uint32_t validBits_ = 0;
};

}  // namespace amrstream::vk
