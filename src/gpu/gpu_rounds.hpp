#pragma once
// One batch of lines traced in rounds on a GPU backend. A round is one submission: the tracing
// kernel advances every live line by up to `steps` steps, writing its points point-major; then
// the compaction kernels pack each line's points into one dense run (a prefix sum over the
// lines' point counts, thread order kept) and the running lines' states for the next round;
// then the point data kernel samples the channels and vorticity at the packed points. Only the
// round's real points and reports are copied back.
//
// The points come back through a StagingRing in pieces of whole points: while the host unpacks
// one piece, the device copies the next ones. runToEnd() submits round r + 1 as soon as the last
// piece of round r is submitted, so that the device traces it while the host unpacks the last
// pieces; its compaction waits for those copies before it overwrites the dense arrays.
// runToEndOnDevice() instead copies each round's dense arrays into device buffers of their own
// (KeptRound), made while the device traces the round, and brings back only the reports.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>

#include "../../shaders/glsl/shared/round_params.h"
#include "flow/round_tracer.hpp"
#include "round_buffers.hpp"
#include "round_kernels.hpp"
#include "staged_layout.hpp"
#include "staging_ring.hpp"
#include "trace_kernel.hpp"
#include "vk/descriptor_pool.hpp"
#include "vk/gpu_timer.hpp"
#include "vk/submission.hpp"
#include "volume_buffers.hpp"

namespace amrstream::gpu {

// Device time of the rounds run so far (when the device has timestamps and timing is on).
struct RoundTimes {
  std::optional<double> traceSeconds;       // the tracing kernel
  std::optional<double> compactionSeconds;  // compaction and point data
  std::size_t rounds = 0;
  std::uint32_t mostLanesPerLine = 0;  // the widest spread of a round (spreadLines)
  // Host wall time: recording and submitting rounds and copies, waiting for rounds, waiting for
  // their copies, unpacking the copies, and the consumer's share.
  double submitSeconds = 0.0, roundWaitSeconds = 0.0, copyWaitSeconds = 0.0, unpackSeconds = 0.0,
         consumeSeconds = 0.0;
};

class GpuRounds final : public flow::RoundTracer {
 public:
  // Everything referenced must outlive the rounds; `buffers` must fit the lines and hold no other
  // rounds' work while these run. With `timeKernels`, timestamps bracket the kernels of every
  // round (they may keep the device from overlapping a round with the previous copy).
  GpuRounds(const vk::Context& ctx, const TraceKernel& trace, const RoundKernels& kernels,
            const VolumeBuffers& device, const flow::VectorVolume& volume,
            std::span<const shared::LineState> lines, const flow::TraceOptions& options,
            RoundBuffers& buffers, StagingRing& staging, bool timeKernels);
  // The same with buffers of its own.
  GpuRounds(const vk::Context& ctx, const TraceKernel& trace, const RoundKernels& kernels,
            const VolumeBuffers& device, const flow::VectorVolume& volume,
            std::span<const shared::LineState> lines, const flow::TraceOptions& options,
            std::unique_ptr<RoundBuffers> buffers, StagingRing& staging, bool timeKernels);

  // Waits for the copies still in the staging ring, which may read these rounds' buffers.
  ~GpuRounds() override;

  std::size_t liveLines() const override { return live_; }
  flow::RoundBlock advance(std::uint32_t steps) override;
  // Read back from the device (the compaction left them first in `states`).
  std::vector<shared::LineState> liveStates() const override;

  // Runs rounds until every line has ended, or until a round leaves `stopAt` live lines or
  // fewer (their states: liveStates()), handing each round's block to `consume` (on this
  // thread) while the next round runs on the device. `stepsFor(live)` gives each round's steps.
  void runToEnd(const std::function<std::uint32_t(std::size_t live)>& stepsFor,
                const std::function<void(flow::RoundBlock&&)>& consume, std::size_t stopAt = 0);

  // The same, leaving each round's points on the device: `keep` gets the round's reports and its
  // points, copied out of the buffers the next round reuses.
  void runToEndOnDevice(
      const std::function<std::uint32_t(std::size_t live)>& stepsFor,
      const std::function<void(std::vector<shared::LineRound>&&, KeptRound&&)>& keep);

  // Rounds of fewer lines than `threads` give each line 2, 4, .. up to 32 invocations, at most
  // `threads` in all, the first of them tracing it (include/line_round.glsl): a subgroup's loads
  // wait for all of its lanes, and lines alone in theirs take their steps sooner. 0: off.
  void spreadLines(std::uint32_t threads) { spreadThreads_ = threads; }

  const RoundTimes& times() const { return times_; }
  std::uint64_t deviceBytes() const;

  // Runs each kernel of a round once, on no lines, and waits: a driver that compiles a pipeline
  // at its first dispatch (lavapipe) compiles it here, in the tracer's setup, not in the first
  // round. The rounds must have no lines.
  void compileByDispatch();

 private:
  // With `everyKernel`, each kernel gets one workgroup at least, and the point data kernel (run
  // when the volume has channels) its own rather than the compaction's count.
  void submitRound(std::uint32_t steps, bool everyKernel = false);
  shared::RoundSummary finishRound();
  // Copies the round submitted last to the host through the staging ring and unpacks it into a
  // block of `lines` lines; calls `afterLastCopy` once every piece's copy is submitted.
  flow::RoundBlock readRound(const shared::RoundSummary& summary, std::size_t lines,
                             const std::function<void()>& afterLastCopy);

  // Runs rounds to the end, or until a round leaves `stopAt` live lines or fewer. `whileTracing`
  // runs on the host after each round is submitted;
  // `take` reads the round just finished and calls its second argument once it no longer needs
  // the round's buffers before the next round overwrites them (after the copies out of them are
  // submitted), which submits the next round.
  void runRounds(
      const std::function<std::uint32_t(std::size_t live)>& stepsFor,
      const std::function<void()>& whileTracing,
      const std::function<void(const shared::RoundSummary&, const std::function<void()>&)>& take,
      std::size_t stopAt = 0);
  // Device buffers for the points of the round submitted last, as many as it may emit but at
  // most `pointsLeft`.
  KeptRound roomForRound(std::uint64_t pointsLeft) const;
  // Copies the round submitted last into `kept` (from roomForRound) and its `lines` reports to
  // the host.
  void keepRound(const shared::RoundSummary& summary, std::size_t lines,
                 const std::function<void()>& afterCopy, KeptRound& kept,
                 std::vector<shared::LineRound>& reports);

  const vk::Context* ctx_;
  const TraceKernel* trace_;
  const RoundKernels* kernels_;
  const VolumeBuffers* device_;
  const flow::VectorVolume* volume_;
  flow::TraceOptions options_;
  shared::TraceParams params_;
  std::unique_ptr<RoundBuffers> ownBuffers_;  // when not the tracer's
  RoundBuffers& buffers_;
  StagingRing& staging_;
  vk::DescriptorPool pool_;
  VkDescriptorSet traceSets_[2]{}, compactionSets_[2]{}, pointDataSet_ = VK_NULL_HANDLE;
  std::optional<vk::GpuTimer> traceTimer_, compactionTimer_;
  std::size_t live_;
  std::size_t roundLines_ = 0;  // lines of the round submitted last
  std::uint32_t spreadThreads_ = 0;
  int parity_ = 0;  // which line-round buffer the next round writes
  RoundTimes times_;
  std::optional<vk::Submission> keepCopy_;
  // Declared last, so that destruction waits for the device before the buffers go.
  vk::Submission round_;
};

}  // namespace amrstream::gpu
