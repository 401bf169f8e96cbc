#pragma once
// Traces whose points stay on the device that traced them until something reads them: each
// round's points where the tracer kept them (KeptRound), the lines and their runs on the host.
// column() gathers the points of a window of lines (about windowBytes of one column, or one
// whole line) from the rounds into pinned memory of the calling thread (gather_kernel.hpp: a
// line's runs lie in several rounds, and there are too many for copy regions; one invocation
// copies one word, whatever the runs' lengths), converts
// positions to physical coordinates there as the host path does when it unpacks rounds, and
// serves the window's lines from it; a writer that reads lines in order thus pulls the points
// through a few pinned buffers instead of holding them all in host memory. Thread-safe: each
// thread has its own buffers and windows; submissions are serialised.

#include <tbb/enumerable_thread_specific.h>

#include <array>
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

#include "../../shaders/glsl/shared/gather_params.h"
#include "flow/line_runs.hpp"
#include "flow/trace_view.hpp"
#include "flow/vector_volume.hpp"
#include "gather_kernel.hpp"
#include "staged_layout.hpp"
#include "vk/buffer.hpp"
#include "vk/descriptor_pool.hpp"
#include "vk/submission.hpp"

namespace amrstream::gpu {

class DeviceTraces final : public flow::TraceView {
 public:
  // The .vtp writer hands its threads 1 MiB of an array's values in turn: a thread's next part
  // lies far beyond its window, so a larger window would be gathered whole for a part of it.
  static constexpr std::uint64_t kWindowBytes = std::uint64_t(1) << 20;

  // `lines` and `runs` as TraceAccumulator::takeLines gives them, `rounds` in the same order,
  // laid out as `layout` says. The context, the kernel and the volume must outlive the traces.
  DeviceTraces(const vk::Context& ctx, const GatherKernel& gather, const flow::VectorVolume& volume,
               const StagedLayout& layout, flow::TraceSet lines, std::vector<KeptRound> rounds,
               std::vector<std::vector<flow::LinePoints>> runs,
               std::uint64_t windowBytes = kWindowBytes);

  const flow::TraceSet& lines() const override { return lines_; }
  // A view of the calling thread's window, valid until its next call for the same column.
  std::span<const float> column(flow::PointColumn column, std::size_t line,
                                std::vector<float>& scratch) const override;
  // Device memory the kept points take.
  std::uint64_t deviceBytes() const;

 private:
  static constexpr std::size_t kColumns = 6;
  struct Window {
    std::size_t firstLine = 0, endLine = 0;  // the lines it holds, in line order
    std::vector<float> values;
  };
  struct Fetcher {
    std::optional<vk::Submission> copy;
    vk::Buffer staging;  // the window's arrays, gathered by the device
    vk::Buffer regions;  // shared::GatherRegion, written by the host
    std::optional<vk::DescriptorPool> pool;
    std::uint32_t poolSets = 0;
    std::array<Window, kColumns> windows;
  };
  // A window's lines, its arrays' places in the staging buffer (one after the other), and the
  // gather's regions (one per run of a line), grouped by the round and array they read.
  struct WindowPlan {
    struct Group {
      std::size_t round, array;
      std::uint32_t first, count;  // its regions
      std::uint32_t words;         // theirs, all together
    };
    std::size_t firstLine = 0, endLine = 0;
    std::uint64_t points = 0, bytes = 0;
    std::vector<std::uint64_t> base;  // per array read
    std::vector<Group> groups;
    std::vector<shared::GatherRegion> regions;
  };

  // The layout's arrays a column is read from: the cells (and region ids) for positions.
  std::vector<std::size_t> arraysOf(flow::PointColumn column) const;
  // The window of `arrays` from `line` on: whole lines, about windowBytes, at least one line.
  WindowPlan planWindow(const std::vector<std::size_t>& arrays, std::size_t line) const;
  // Runs the plan's gather into the fetcher's staging buffer and waits for it.
  void gather(Fetcher& fetcher, const WindowPlan& plan) const;
  // Fills the windows of `column` (for positions: of both parts) with the lines from `line` on.
  void fetch(Fetcher& fetcher, flow::PointColumn column, std::size_t line) const;

  const vk::Context* ctx_;
  const GatherKernel* gather_;
  const flow::VectorVolume* volume_;
  flow::TraceSet lines_;
  std::vector<KeptRound> rounds_;
  flow::LineRuns runs_;
  std::vector<std::uint64_t> arrayBytes_;       // per array of the layout, bytes per point
  std::size_t vorticityArray_, regionIdArray_;  // arrayBytes_.size() when absent
  std::uint64_t windowBytes_;
  mutable std::mutex submitting_;  // the context's command pool and queue
  mutable tbb::enumerable_thread_specific<Fetcher> fetchers_;
};

}  // namespace amrstream::gpu
