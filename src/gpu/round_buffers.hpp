#pragma once
// The device buffers of a batch of lines traced in rounds, and the host-visible copies a round's
// output is read back into: `lines` line slots and `pointSlots` output slots shared by a round's
// lines (a round of n live lines and k slots each needs n * k). A tracer keeps them for the next
// batch or trace that fits, since making pinned host memory is slow.
//
// Per line: the states the next round starts from (compacted after each round), the states the
// round ends with (one per thread), the round reports (two, alternating between rounds, so that
// a round may run while the previous one's reports are still being copied), the compaction's
// prefix, and the host copy of the reports.
// Per output slot: the round's point-major output (position, time, vector, region id) and its
// dense copy with the point data.

#include <cstdint>
#include <span>
#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "flow/line_plan.hpp"
#include "vk/buffer.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::gpu {

struct RoundBuffers {
  // `regionIds`: the points' region ids come back too, for positions relative to their regions
  // (VectorVolume::deepPositions).
  RoundBuffers(const vk::Context& ctx, std::size_t lines, std::uint64_t pointSlots,
               std::size_t channelsPerPoint, bool vorticity, bool regionIds);

  // Whether these buffers serve a batch of this size and point data.
  bool fits(std::size_t lines, std::uint64_t pointSlots, std::size_t channelsPerPoint,
            bool vorticity, bool regionIds) const;
  // The batch's starting states, copied into `states` (and the submission waited for).
  void setStates(const vk::Context& ctx, std::span<const shared::LineState> lines);
  // The first `count` states of `states` (after all work submitted before).
  std::vector<shared::LineState> readStates(const vk::Context& ctx, std::size_t count);

  // The bytes the fields below take per line and per output slot, for budgeting.
  static flow::RoundCosts costs(std::size_t channelCount, bool vorticity);

  std::size_t lineCapacity;
  std::uint64_t pointCapacity;
  std::size_t channelCount;
  bool withVorticity;
  bool withRegionIds;

  vk::Buffer params;  // shared::TraceParams, host-written before each round
  vk::Buffer states;
  // Host copies of `states`, kept because making them is slow; the download one is made by the
  // first readStates().
  vk::Buffer statesUpload, statesDownload;
  vk::Buffer roundStates;
  vk::Buffer lineRounds[2];
  vk::Buffer prefix;
  vk::Buffer blockSums;
  vk::Buffer summary;  // shared::RoundSummary; also the point data's indirect dispatch

  // Point-major output of the tracing kernel.
  vk::Buffer positions, times, vectors, regionIds;
  // Dense output of the compaction and the point data kernel.
  vk::Buffer densePositions, denseTimes, denseVectors, denseRegionIds, channels, vorticity;

  // Host-visible copies of the summary and the reports; the points come through a StagingRing.
  vk::Buffer summaryOut;
  vk::Buffer lineRoundsOut;
};

}  // namespace amrstream::gpu
