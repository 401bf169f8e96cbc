#include "device_traces.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "point_positions.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/descriptor_writes.hpp"

namespace amrstream::gpu {

namespace {

std::size_t columnIndex(flow::PointColumn column) { return static_cast<std::size_t>(column); }

}  // namespace

DeviceTraces::DeviceTraces(const vk::Context& ctx, const GatherKernel& gather,
                           const flow::VectorVolume& volume, const StagedLayout& layout,
                           flow::TraceSet lines, std::vector<KeptRound> rounds,
                           std::vector<std::vector<flow::LinePoints>> runs,
                           std::uint64_t windowBytes)
    : ctx_(&ctx),
      gather_(&gather),
      volume_(&volume),
      lines_(std::move(lines)),
      rounds_(std::move(rounds)),
      vorticityArray_(layout.vorticity()),
      regionIdArray_(layout.regionIds()),
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

std::vector<std::size_t> DeviceTraces::arraysOf(flow::PointColumn column) const {
  using flow::PointColumn;
  switch (column) {
    case PointColumn::Positions:
    case PointColumn::PositionsLow:
      if (lines_.precisePositions) return {StagedLayout::kCells, regionIdArray_};
      return {StagedLayout::kCells};
    case PointColumn::Times:
      return {StagedLayout::kTimes};
    case PointColumn::Vectors:
      return {StagedLayout::kVectors};
    case PointColumn::Channels:
      return {StagedLayout::kChannels};
    case PointColumn::Vorticity:
      return {vorticityArray_};
  }
  return {};
}

DeviceTraces::WindowPlan DeviceTraces::planWindow(const std::vector<std::size_t>& arrays,
                                                  std::size_t line) const {
  std::uint64_t bytesPerPoint = 0;
  for (const std::size_t array : arrays) bytesPerPoint += arrayBytes_[array];
  // Whole lines from `line` on, as many as fit the window's bytes (at least one).
  const std::vector<std::uint64_t>& offsets = lines_.offsets;
  const std::uint64_t most = std::max<std::uint64_t>(1, windowBytes_ / bytesPerPoint);
  WindowPlan plan;
  plan.firstLine = line;
  plan.endLine = std::upper_bound(offsets.begin() + line + 1, offsets.end(), offsets[line] + most) -
                 offsets.begin() - 1;
  plan.endLine = std::clamp(plan.endLine, line + 1, lines_.lineCount());
  plan.points = offsets[plan.endLine] - offsets[line];
  for (const std::size_t array : arrays) {
    plan.base.push_back(plan.bytes);
    plan.bytes += plan.points * arrayBytes_[array];
  }

  // The regions of round r's array arrays[k] are groups[r * arrays.size() + k].
  std::vector<std::vector<shared::GatherRegion>> groups(rounds_.size() * arrays.size());
  const auto words = [](std::uint64_t bytes) { return static_cast<std::uint32_t>(bytes / 4); };
  for (std::size_t l = line; l < plan.endLine; ++l) {
    std::uint64_t point = offsets[l] - offsets[line];
    for (const flow::PointRun& run : runs_.of(l)) {
      if (run.count == 0) continue;
      for (std::size_t k = 0; k < arrays.size(); ++k) {
        const std::uint64_t bytes = arrayBytes_[arrays[k]];
        groups[run.round * arrays.size() + k].push_back({words(run.first * bytes),
                                                         words(plan.base[k] + point * bytes),
                                                         words(run.count * bytes), 0});
      }
      point += run.count;
    }
  }
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (groups[g].empty()) continue;
    std::uint32_t words = 0;
    for (shared::GatherRegion& region : groups[g]) {
      region.firstWord = words;
      words += region.words;
    }
    plan.groups.push_back({g / arrays.size(), arrays[g % arrays.size()],
                           std::uint32_t(plan.regions.size()), std::uint32_t(groups[g].size()),
                           words});
    plan.regions.insert(plan.regions.end(), groups[g].begin(), groups[g].end());
  }
  return plan;
}

void DeviceTraces::gather(Fetcher& fetcher, const WindowPlan& plan) const {
  {
    const std::lock_guard lock(submitting_);
    if (fetcher.staging.size() < plan.bytes)
      fetcher.staging = vk::Buffer::readback(
          *ctx_, std::max(plan.bytes, windowBytes_),
          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, "trace window");
    const std::uint64_t regionBytes = plan.regions.size() * sizeof(shared::GatherRegion);
    if (fetcher.regions.size() < regionBytes)
      fetcher.regions = vk::Buffer::upload(*ctx_, 2 * regionBytes,
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "gather regions");
    std::memcpy(fetcher.regions.mapped().data(), plan.regions.data(), regionBytes);
    if (!fetcher.pool || fetcher.poolSets < plan.groups.size()) {
      fetcher.poolSets = std::max<std::uint32_t>(16, 2 * std::uint32_t(plan.groups.size()));
      const VkDescriptorPoolSize perSet{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                        AMRSTREAM_GATHER_BINDING_COUNT};
      fetcher.pool.emplace(*ctx_, fetcher.poolSets, std::span(&perSet, 1));
    } else {
      fetcher.pool->reset();
    }
    std::vector<VkDescriptorSet> sets;
    for (const WindowPlan::Group& group : plan.groups) {
      sets.push_back(fetcher.pool->allocate(gather_->setLayout.get()));
      vk::DescriptorWrites("gather", AMRSTREAM_GATHER_BINDING_COUNT)
          .set(AMRSTREAM_BINDING_GATHER_SOURCE, rounds_[group.round].arrays[group.array])
          .set(AMRSTREAM_BINDING_GATHER_TARGET, fetcher.staging)
          .set(AMRSTREAM_BINDING_GATHER_REGIONS, fetcher.regions)
          .write(*ctx_, sets.back());
    }
    if (!fetcher.copy) fetcher.copy.emplace(*ctx_);
    const std::uint32_t most = ctx_->limits().maxComputeWorkGroupCount[0];
    fetcher.copy->submit([&](VkCommandBuffer cmd) {
      // The rounds were copied into their arrays by earlier submissions.
      vk::memoryBarrier(cmd, vk::access::kTransferWrite,
                        {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT});
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gather_->pipeline.get());
      for (std::size_t g = 0; g < sets.size(); ++g) {
        const WindowPlan::Group& group = plan.groups[g];
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gather_->layout.get(), 0, 1,
                                &sets[g], 0, nullptr);
        // Per word where the mean run is shorter than a workgroup's words, else per run.
        const bool perWord = group.words < std::uint64_t(group.count) * AMRSTREAM_GATHER_GROUP;
        const std::uint64_t workgroups =
            perWord ? (group.words + AMRSTREAM_GATHER_GROUP - 1) / AMRSTREAM_GATHER_GROUP
                    : group.count;
        for (std::uint64_t done = 0; done < workgroups; done += most) {
          const shared::GatherParams params =
              perWord
                  ? shared::GatherParams{group.first, group.count,
                                         std::uint32_t(done * AMRSTREAM_GATHER_GROUP), group.words}
                  : shared::GatherParams{group.first + std::uint32_t(done), 0, 0, 0};
          vkCmdPushConstants(cmd, gather_->layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                             sizeof(params), &params);
          vkCmdDispatch(cmd, std::uint32_t(std::min<std::uint64_t>(most, workgroups - done)), 1, 1);
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
}

void DeviceTraces::fetch(Fetcher& fetcher, flow::PointColumn column, std::size_t line) const {
  using flow::PointColumn;
  const WindowPlan plan = planWindow(arraysOf(column), line);
  gather(fetcher, plan);
  const std::byte* staged = fetcher.staging.mapped().data();
  if (column == PointColumn::Positions || column == PointColumn::PositionsLow) {
    Window& high = fetcher.windows[columnIndex(PointColumn::Positions)];
    Window& low = fetcher.windows[columnIndex(PointColumn::PositionsLow)];
    const bool precise = lines_.precisePositions;
    high.values.resize(plan.points * 3);
    low.values.resize(precise ? plan.points * 3 : 0);
    toPhysicalPositions(
        *volume_, reinterpret_cast<const glm::vec3*>(staged + plan.base[0]),
        precise ? reinterpret_cast<const std::int32_t*>(staged + plan.base[1]) : nullptr,
        plan.points, reinterpret_cast<glm::vec3*>(high.values.data()),
        precise ? reinterpret_cast<glm::vec3*>(low.values.data()) : nullptr);
    high.firstLine = low.firstLine = plan.firstLine;
    high.endLine = low.endLine = plan.endLine;
    return;
  }
  Window& window = fetcher.windows[columnIndex(column)];
  window.values.resize(plan.bytes / sizeof(float));
  std::memcpy(window.values.data(), staged, plan.bytes);
  window.firstLine = plan.firstLine;
  window.endLine = plan.endLine;
}

}  // namespace amrstream::gpu
