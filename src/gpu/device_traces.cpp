#include "device_traces.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <stdexcept>
#include <utility>

#include "../../shaders/glsl/shared/gather_params.h"
#include "point_positions.hpp"
#include "vk/context.hpp"
#include "vk/commands.hpp"

namespace amrstream::gpu {

namespace {

std::size_t columnIndex(flow::PointColumn column) { return static_cast<std::size_t>(column); }

}  // namespace

DeviceTraces::DeviceTraces(const vk::Context& ctx, const GatherKernel& gather,
                           const flow::VectorVolume& volume,
                           const StagedLayout& layout, flow::TraceSet lines,
                           std::vector<KeptRound> rounds,
                           std::vector<std::vector<flow::LinePoints>> runs,
                           std::uint64_t windowBytes)
    : ctx_(&ctx), gather_(&gather), volume_(&volume), lines_(std::move(lines)),
      rounds_(std::move(rounds)),
      vorticityArray_(layout.vorticity()), regionIdArray_(layout.regionIds()),
      windowBytes_(std::max<std::uint64_t>(windowBytes, 1)) {
  if (runs.size() != rounds_.size())
    throw std::invalid_argument("DeviceTraces: one list of runs per round");
  for (const StagedArray& array : layout.arrays()) arrayBytes_.push_back(array.bytesPerPoint);
  for (const KeptRound& round : rounds_)
    if (round.arrays.size() != arrayBytes_.size())
      throw std::invalid_argument("DeviceTraces: a round's arrays do not match the layout");
  if (lines_.precisePositions != (regionIdArray_ < arrayBytes_.size()) ||
      lines_.withVorticity != (vorticityArray_ < arrayBytes_.size()))
    throw std::invalid_argument("DeviceTraces: the lines' columns do not match the layout");
  runs_ = flow::LineRuns(lines_.lineCount(), runs);
}

std::uint64_t DeviceTraces::deviceBytes() const {
  std::uint64_t bytes = 0;
  for (const KeptRound& round : rounds_)
    for (const vk::Buffer& array : round.arrays) bytes += array.size();
  return bytes;
}

std::span<const float> DeviceTraces::column(flow::PointColumn column, std::size_t line,
                                            std::vector<float>&) const {
  const std::size_t width = flow::columnWidth(lines_, column);
  if (width == 0 || !flow::holdsColumn(lines_, column) || lines_.pointCount(line) == 0) return {};
  Fetcher& fetcher = fetchers_.local();
  const Window* window = &fetcher.windows[columnIndex(column)];
  if (line < window->firstLine || line >= window->endLine) {
    fetch(fetcher, column, line);
    window = &fetcher.windows[columnIndex(column)];
  }
  const std::uint64_t first = lines_.offsets[line] - lines_.offsets[window->firstLine];
  return {window->values.data() + first * width, lines_.pointCount(line) * width};
}

void DeviceTraces::fetch(Fetcher& fetcher, flow::PointColumn column, std::size_t line) const {
  using flow::PointColumn;
  const bool positions = column == PointColumn::Positions || column == PointColumn::PositionsLow;
  // The arrays to copy: the cells (and region ids) for positions, else the column's own.
  std::vector<std::size_t> arrays;
  switch (column) {
    case PointColumn::Positions:
    case PointColumn::PositionsLow:
      arrays.push_back(StagedLayout::kCells);
      if (lines_.precisePositions) arrays.push_back(regionIdArray_);
      break;
    case PointColumn::Times:
      arrays.push_back(StagedLayout::kTimes);
      break;
    case PointColumn::Vectors:
      arrays.push_back(StagedLayout::kVectors);
      break;
    case PointColumn::Channels:
      arrays.push_back(StagedLayout::kChannels);
      break;
    case PointColumn::Vorticity:
      arrays.push_back(vorticityArray_);
      break;
  }
  std::uint64_t bytesPerPoint = 0;
  for (const std::size_t array : arrays) bytesPerPoint += arrayBytes_[array];

  // Whole lines from `line` on, as many as fit the window's bytes (at least one).
  const std::vector<std::uint64_t>& offsets = lines_.offsets;
  const std::uint64_t most = std::max<std::uint64_t>(1, windowBytes_ / bytesPerPoint);
  std::size_t end = std::upper_bound(offsets.begin() + line + 1, offsets.end(),
                                     offsets[line] + most) -
                    offsets.begin() - 1;
  end = std::clamp(end, line + 1, lines_.lineCount());
  const std::uint64_t points = offsets[end] - offsets[line];

  // Each array of the window lies whole in the staging buffer, one after the other; each run of
  // a line is one region of the copy from its round's array.
  std::map<std::pair<std::size_t, std::size_t>, std::vector<shared::GatherRegion>> groups;
  std::vector<std::uint64_t> base;
  std::uint64_t at = 0;
  for (const std::size_t array : arrays) {
    base.push_back(at);
    at += points * arrayBytes_[array];
  }
  const auto words = [](std::uint64_t bytes) { return static_cast<std::uint32_t>(bytes / 4); };
  for (std::size_t l = line; l < end; ++l) {
    std::uint64_t point = offsets[l] - offsets[line];
    for (const flow::PointRun& run : runs_.of(l)) {
      if (run.count == 0) continue;
      for (std::size_t k = 0; k < arrays.size(); ++k) {
        const std::uint64_t bytes = arrayBytes_[arrays[k]];
        groups[{run.round, arrays[k]}].push_back({words(run.first * bytes),
                                                  words(base[k] + point * bytes),
                                                  words(run.count * bytes), 0});
      }
      point += run.count;
    }
  }
  std::vector<shared::GatherRegion> regions;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> spans;  // per group: first, count
  for (const auto& [source, list] : groups) {
    spans.emplace_back(static_cast<std::uint32_t>(regions.size()),
                       static_cast<std::uint32_t>(list.size()));
    regions.insert(regions.end(), list.begin(), list.end());
  }

  {
    const std::lock_guard lock(submitting_);
    if (fetcher.copy) fetcher.copy->wait();
    if (fetcher.staging.size() < at)
      fetcher.staging = vk::Buffer::readback(
          *ctx_, std::max(at, windowBytes_),
          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, "trace window");
    const std::uint64_t regionBytes = regions.size() * sizeof(shared::GatherRegion);
    if (fetcher.regions.size() < regionBytes)
      fetcher.regions = vk::Buffer::upload(*ctx_, 2 * regionBytes,
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "gather regions");
    std::memcpy(fetcher.regions.mapped().data(), regions.data(), regionBytes);
    if (!fetcher.pool || fetcher.poolSets < groups.size()) {
      fetcher.poolSets = std::max<std::uint32_t>(16, 2 * std::uint32_t(groups.size()));
      const VkDescriptorPoolSize perSet{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kGatherBindingCount};
      fetcher.pool.emplace(*ctx_, fetcher.poolSets, std::span(&perSet, 1));
    } else {
      fetcher.pool->reset();
    }
    std::vector<VkDescriptorSet> sets;
    for (const auto& [source, list] : groups) {
      sets.push_back(fetcher.pool->allocate(gather_->setLayout.get()));
      const std::array<vk::DescriptorTarget, kGatherBindingCount> targets{
          vk::DescriptorTarget{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                               rounds_[source.first].arrays[source.second].handle()},
          vk::DescriptorTarget{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fetcher.staging.handle()},
          vk::DescriptorTarget{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, fetcher.regions.handle()}};
      vk::writeDescriptors(*ctx_, sets.back(), targets);
    }
    if (!fetcher.copy) fetcher.copy.emplace(*ctx_);
    const std::uint32_t most = ctx_->limits().maxComputeWorkGroupCount[0];
    fetcher.copy->submit([&](VkCommandBuffer cmd) {
      // The rounds were copied into their arrays by earlier submissions.
      vk::memoryBarrier(cmd, vk::access::kTransferWrite,
                        {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT});
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gather_->pipeline.get());
      for (std::size_t g = 0; g < sets.size(); ++g) {
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gather_->layout.get(), 0, 1,
                                &sets[g], 0, nullptr);
        for (std::uint32_t done = 0; done < spans[g].second; done += most) {
          const shared::GatherParams params{spans[g].first + done};
          vkCmdPushConstants(cmd, gather_->layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                             sizeof(params), &params);
          vkCmdDispatch(cmd, std::min(most, spans[g].second - done), 1, 1);
        }
      }
      vk::memoryBarrier(cmd, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                        vk::access::kHostRead);
    });
  }
  fetcher.copy->wait();
  // The writer calls this after the tracing's own check: a file written from points the layer
  // found fault with is not made.
  if (ctx_->validationErrorCount() > 0)
    throw std::runtime_error(fmt::format("the Vulkan validation layer reported {} errors",
                                         ctx_->validationErrorCount()));
  fetcher.staging.invalidateMapped();
  const std::byte* staged = fetcher.staging.mapped().data();

  if (positions) {
    Window& high = fetcher.windows[columnIndex(PointColumn::Positions)];
    Window& low = fetcher.windows[columnIndex(PointColumn::PositionsLow)];
    high.values.resize(points * 3);
    low.values.resize(lines_.precisePositions ? points * 3 : 0);
    toPhysicalPositions(*volume_, reinterpret_cast<const glm::vec3*>(staged + base[0]),
                        lines_.precisePositions
                            ? reinterpret_cast<const std::int32_t*>(staged + base[1])
                            : nullptr,
                        points, reinterpret_cast<glm::vec3*>(high.values.data()),
                        lines_.precisePositions ? reinterpret_cast<glm::vec3*>(low.values.data())
                                                : nullptr);
    high.firstLine = low.firstLine = line;
    high.endLine = low.endLine = end;
    return;
  }
  Window& window = fetcher.windows[columnIndex(column)];
  window.values.resize(points * bytesPerPoint / sizeof(float));
  std::memcpy(window.values.data(), staged, points * bytesPerPoint);
  window.firstLine = line;
  window.endLine = end;
}

}  // namespace amrstream::gpu
