#include "round_buffers.hpp"

#include <cstring>
#include <glm/glm.hpp>
#include <stdexcept>

#include "../../shaders/glsl/shared/round_params.h"
#include "../../shaders/glsl/shared/trace_params.h"
#include "util/parallel_copy.hpp"
#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"

namespace amrstream::gpu {

namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
constexpr VkBufferUsageFlags kCopied = kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

vk::Buffer device(const vk::Context& ctx, std::uint64_t bytes, const char* name,
                  VkBufferUsageFlags usage = kStorage) {
  return vk::Buffer::deviceLocal(ctx, bytes, usage, name);
}

vk::Buffer host(const vk::Context& ctx, std::uint64_t bytes, const char* name) {
  return vk::Buffer::readback(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, name);
}

std::uint64_t blocksOf(std::size_t lines) {
  return (lines + AMRSTREAM_COMPACTION_GROUP - 1) / AMRSTREAM_COMPACTION_GROUP;
}

}  // namespace

flow::RoundCosts RoundBuffers::costs(std::size_t channelCount, bool vorticity) {
  const std::uint64_t pointData =
      channelCount * sizeof(float) + (vorticity ? sizeof(glm::vec3) : 0);
  const std::uint64_t emitted = 2 * sizeof(glm::vec3) + sizeof(float) + sizeof(std::int32_t);
  // The emitted arrays, their dense copies and the point data; the host receives the dense
  // arrays through a staging ring of its own size.
  return {3 * sizeof(shared::LineState) + 3 * sizeof(shared::LineRound) + sizeof(glm::uvec2),
          2 * emitted + pointData};
}

RoundBuffers::RoundBuffers(const vk::Context& ctx, std::size_t lines, std::uint64_t pointSlots,
                           std::size_t channelsPerPoint, bool vorticityToo, bool regionIdsToo)
    : lineCapacity(lines),
      pointCapacity(pointSlots),
      channelCount(channelsPerPoint),
      withVorticity(vorticityToo),
      withRegionIds(regionIdsToo) {
  const std::uint64_t n = lineCapacity, p = pointCapacity;
  params = vk::Buffer::upload(ctx, sizeof(shared::TraceParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                              "round params");
  states = device(ctx, n * sizeof(shared::LineState), "line states",
                  kCopied | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  statesUpload = vk::Buffer::upload(ctx, n * sizeof(shared::LineState),
                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "line states (upload)");

  roundStates = device(ctx, n * sizeof(shared::LineState), "round states");
  lineRounds[0] = device(ctx, n * sizeof(shared::LineRound), "line rounds (even)", kCopied);
  lineRounds[1] = device(ctx, n * sizeof(shared::LineRound), "line rounds (odd)", kCopied);
  prefix = device(ctx, n * sizeof(glm::uvec2), "line prefix");
  blockSums = device(ctx, blocksOf(n) * sizeof(glm::uvec2), "block sums");
  summary = device(ctx, sizeof(shared::RoundSummary), "round summary",
                   kCopied | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);

  positions = device(ctx, p * sizeof(glm::vec3), "round positions");
  times = device(ctx, p * sizeof(float), "round times");
  vectors = device(ctx, p * sizeof(glm::vec3), "round vectors");
  regionIds = device(ctx, p * sizeof(std::int32_t), "round region ids", kCopied);
  densePositions = device(ctx, p * sizeof(glm::vec3), "dense positions", kCopied);
  denseTimes = device(ctx, p * sizeof(float), "dense times", kCopied);
  denseVectors = device(ctx, p * sizeof(glm::vec3), "dense vectors", kCopied);
  denseRegionIds = device(ctx, p * sizeof(std::int32_t), "dense region ids", kCopied);
  channels = device(ctx, p * channelCount * sizeof(float), "dense channels", kCopied);
  vorticity = device(ctx, withVorticity ? p * sizeof(glm::vec3) : 0, "dense vorticity", kCopied);

  summaryOut = host(ctx, sizeof(shared::RoundSummary), "round summary (host)");
  lineRoundsOut = host(ctx, n * sizeof(shared::LineRound), "line rounds (host)");
}

bool RoundBuffers::fits(std::size_t lines, std::uint64_t pointSlots, std::size_t channelsPerPoint,
                        bool vorticityToo, bool regionIdsToo) const {
  return lines <= lineCapacity && pointSlots <= pointCapacity && channelsPerPoint == channelCount &&
         vorticityToo == withVorticity && regionIdsToo == withRegionIds;
}

void RoundBuffers::setStates(const vk::Context& ctx, std::span<const shared::LineState> lines) {
  if (lines.size() > lineCapacity) throw std::logic_error("RoundBuffers: too many lines");
  if (lines.empty()) return;
  copyParallel(std::as_bytes(lines), statesUpload.mapped());
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    // The previous batch's rounds are done (their submissions were waited for).
    const VkBufferCopy region{0, 0, lines.size_bytes()};
    vkCmdCopyBuffer(cmd, statesUpload.handle(), states.handle(), 1, &region);
    vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kAny);
  });
}

std::vector<shared::LineState> RoundBuffers::readStates(const vk::Context& ctx, std::size_t count) {
  if (count > lineCapacity) throw std::logic_error("RoundBuffers: too many lines");
  std::vector<shared::LineState> lines(count);
  if (count == 0) return lines;
  const VkDeviceSize bytes = count * sizeof(shared::LineState);
  if (statesDownload.size() == 0)
    statesDownload = host(ctx, lineCapacity * sizeof(shared::LineState), "line states (download)");
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, vk::access::kAny, vk::access::kTransferRead);
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, states.handle(), statesDownload.handle(), 1, &region);
    vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kHostRead);
  });
  statesDownload.invalidateMapped();
  std::memcpy(lines.data(), statesDownload.mapped().data(), bytes);
  return lines;
}

}  // namespace amrstream::gpu
