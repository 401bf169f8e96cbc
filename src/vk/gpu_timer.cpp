#include "vk/gpu_timer.hpp"

#include <array>
#include <vector>

#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

namespace {

std::uint32_t timestampValidBits(const Context& ctx) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &count, families.data());
  return ctx.queueFamilyIndex() < count ? families[ctx.queueFamilyIndex()].timestampValidBits : 0;
}

}  // namespace

GpuTimer::GpuTimer(const Context& ctx)
    : device_(ctx.device()),
      secondsPerTick_(double(ctx.limits().timestampPeriod) * 1e-9),
      validBits_(timestampValidBits(ctx)) {
  if (validBits_ == 0 || !(secondsPerTick_ > 0.0)) return;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2;
  VkQueryPool pool = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool));
  pool_ = UniqueHandle<VkQueryPool>(device_, pool);
}

void GpuTimer::start(VkCommandBuffer cmd) const {
  if (!supported()) return;
  vkCmdResetQueryPool(cmd, pool_.get(), 0, 2);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), 0);
}

void GpuTimer::stop(VkCommandBuffer cmd) const {
  if (!supported()) return;
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), 1);
}

std::optional<double> GpuTimer::seconds() const {
  if (!supported()) return std::nullopt;
  std::array<std::uint64_t, 2> ticks{};
  AMRSTREAM_VK_CHECK(vkGetQueryPoolResults(device_, pool_.get(), 0, 2, sizeof(ticks), ticks.data(),
                                           sizeof(std::uint64_t),
                                           VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  const std::uint64_t mask =
      validBits_ >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << validBits_) - 1;
  const std::uint64_t elapsed = ((ticks[1] & mask) - (ticks[0] & mask)) & mask;
  return double(elapsed) * secondsPerTick_;
}

}  // namespace amrstream::vk
