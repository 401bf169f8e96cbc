#include "api/series_playback.hpp"

#include <limits>

#include "api/handles.hpp"
#include "gpu/pathline_stepper.hpp"
#include "gpu/trace_kernel.hpp"
#include "gpu/vector_probe.hpp"
#include "vk/context.hpp"

namespace amrstream {

// The backend's probe kernel and stepper, and the interval's snapshots on the device.
struct SeriesPlayback::Device {
  const vk::Context& ctx;
  gpu::TraceKernel kernel;
  gpu::PathlineStepper stepper;
  std::unique_ptr<gpu::VectorProbe> probeA, probeB;

  Device(const vk::Context& context, gpu::Backend backend)
      : ctx(context),
        kernel(gpu::createTraceKernel(context, backend, gpu::KernelProgram::LocateProbe)),
        stepper(context, kernel) {}
};

SeriesPlayback::SeriesPlayback(std::vector<SnapshotFile> series,
                               const flow::PathlineOptions& options, FieldOptions field,
                               DeclaredUnits units, const flow::VectorVolume& first,
                               std::span<const glm::dvec3> seeds, const vk::Context* ctx,
                               gpu::Backend backend, const gpu::VolumeBuffers* firstDevice)
    : series_(std::move(series)),
      options_(options),
      field_(std::move(field)),
      units_(std::move(units)),
      firstVolume_(&first),
      tracer_(seeds, options, first.vectorName, first.channelNames),
      time_(options.startTime) {
  std::tie(first_, last_) = snapshotsUsed(series_, options.startTime, options.endTime);
  index_ = first_;
  tracer_.planStorage(snapshotTimes(series_, first_, last_));
  b_ = loadSnapshot(series_[index_ + 1], field_, units_, false);
  checkLikeTheFirst(volumeOf(*b_->field), series_[index_ + 1].path, first);
  loadAhead();
  if (ctx) {
    device_ = std::make_unique<Device>(*ctx, backend);
    device_->probeA =
        firstDevice ? std::make_unique<gpu::VectorProbe>(*ctx, device_->kernel, first, *firstDevice)
                    : std::make_unique<gpu::VectorProbe>(*ctx, device_->kernel, first);
    device_->probeB =
        std::make_unique<gpu::VectorProbe>(*ctx, device_->kernel, volumeOf(*b_->field));
    device_->stepper.bind(*device_->probeA, *device_->probeB);
  }
}

SeriesPlayback::~SeriesPlayback() {
  if (next_.valid()) next_.wait();
}

flow::Snapshot SeriesPlayback::snapshotA() const {
  return {series_[index_].time, a_ ? &volumeOf(*a_->field) : firstVolume_,
          probeSampler(device_ ? device_->probeA.get() : nullptr)};
}

flow::Snapshot SeriesPlayback::snapshotB() const {
  return {series_[index_ + 1].time, &volumeOf(*b_->field),
          probeSampler(device_ ? device_->probeB.get() : nullptr)};
}

void SeriesPlayback::loadAhead() {
  if (index_ + 2 <= last_)
    next_ = std::async(std::launch::async, [this, i = index_ + 2] {
      return loadSnapshot(series_[i], field_, units_, false);
    });
}

void SeriesPlayback::nextInterval() {
  ++index_;
  std::unique_ptr<LoadedSnapshot> b = next_.get();
  checkLikeTheFirst(volumeOf(*b->field), series_[index_ + 1].path, *firstVolume_);
  loadAhead();
  if (device_) {
    vkQueueWaitIdle(device_->ctx.queue());
    device_->probeA = std::move(device_->probeB);
    device_->probeB =
        std::make_unique<gpu::VectorProbe>(device_->ctx, device_->kernel, volumeOf(*b->field));
    device_->stepper.bind(*device_->probeA, *device_->probeB);
  }
  a_ = std::move(b_);
  b_ = std::move(b);
}

std::size_t SeriesPlayback::advance(std::uint32_t steps) {
  if (done_) return 0;
  const std::uint64_t before = tracer_.stepCount();
  const double until = std::min(series_[index_ + 1].time, options_.endTime);
  const double stopAt = time_ + double(steps) * options_.stepSize;
  // To a sliver of a step, as the tracer's steps end (float rounding must not leave an empty
  // frame at the interval's end).
  const bool wholeInterval = stopAt + 1e-4 * options_.stepSize >= until;
  tracer_.advance(snapshotA(), snapshotB(), device_ ? &device_->stepper : nullptr,
                  wholeInterval ? std::numeric_limits<double>::infinity() : stopAt);
  started_ = true;
  time_ = wholeInterval ? until : stopAt;
  if (wholeInterval) {
    if (index_ + 1 >= last_ || until >= options_.endTime) {
      tracer_.finish();
      done_ = true;
    } else {
      nextInterval();
    }
  }
  recent_ = tracer_.lastGrowth();
  stale_ = true;
  return std::size_t(tracer_.stepCount() - before);
}

bool SeriesPlayback::finished() const {
  return done_ || (started_ && tracer_.runningCount() == 0 && !(options_.releaseEvery > 0.0));
}

const flow::TraceSet& SeriesPlayback::traces() const {
  if (stale_) {
    traces_ = tracer_.pathlines();
    stale_ = false;
  }
  return traces_;
}

}  // namespace amrstream
