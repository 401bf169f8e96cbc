#pragma once
// Pathlines' steps on the device (flow::IntervalStepper). Through an interval the particles'
// states stay in device buffers; each RK4 stage is a dispatch of the stage kernel
// (shaders/glsl/pathline_stage.comp) after the backend's probe kernel has sampled both of the
// interval's snapshots at the stage's points (both resident: their VectorProbes' device copies).
// A round of steps is recorded into one command buffer and submitted once; its points come back
// through host-visible buffers, two sets of them, so that the device runs the next round while
// the host collects this one.

#include <cstdint>
#include <functional>
#include <memory>

#include "flow/interval_stepper.hpp"
#include "round_kernels.hpp"
#include "trace_kernel.hpp"
#include "vector_probe.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::gpu {

class PathlineStepper final : public flow::IntervalStepper {
 public:
  // `probeKernel`: createTraceKernel(ctx, backend, KernelProgram::LocateProbe). It and the
  // context must outlive the stepper. A round's output takes at most about `roundBytes` (one
  // step at least), twice over; a move() takes at most `mostParticles` particles (by default
  // within every backend's dispatch limits, with state buffers of about half a GB).
  PathlineStepper(const vk::Context& ctx, const TraceKernel& probeKernel,
                  std::uint64_t roundBytes = std::uint64_t(128) << 20,
                  std::size_t mostParticles = std::size_t(1) << 22);
  ~PathlineStepper() override;
  PathlineStepper(const PathlineStepper&) = delete;
  PathlineStepper& operator=(const PathlineStepper&) = delete;

  // The snapshots of the next move()'s interval: a's and b's volumes on the device. Both must
  // outlive that move().
  void bind(const VectorProbe& a, const VectorProbe& b);

  std::size_t mostParticles() const override;
  void move(const flow::IntervalPlan& plan,
            const std::function<void(const flow::StepRows&)>& collect) override;

  // Host time so far: waiting for the device's rounds (what collecting the last did not hide),
  // and handing their points to `collect`.
  struct Times {
    std::size_t rounds = 0, dispatches = 0;
    double deviceSeconds = 0.0, collectSeconds = 0.0;
  };
  const Times& times() const { return times_; }

 private:
  struct Buffers;
  struct Kernel;
  void reserve(std::size_t particles, std::size_t rows, std::size_t scheduleSteps,
               std::size_t channels);

  const vk::Context* ctx_;
  const TraceKernel* probeKernel_;
  std::uint64_t roundBytes_;
  std::size_t mostParticles_;
  const VectorProbe* a_ = nullptr;
  const VectorProbe* b_ = nullptr;
  std::unique_ptr<Kernel> kernel_;
  std::unique_ptr<PointDataKernel> pointData_;  // made once a snapshot has channels
  std::unique_ptr<Buffers> buffers_;
  Times times_;
};

}  // namespace amrstream::gpu
