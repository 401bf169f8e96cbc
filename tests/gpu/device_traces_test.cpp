// Traces kept on the device (GpuTracer::traceOnDevice, read through DeviceTraces) against the
// same tracer's traces collected in host memory: the same lines, and every column of every line
// bit for bit, read through windows of a few points (lines longer than a window, windows ending
// between runs of rounds), in order, backwards, and from many threads at once.

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <string>

#include "deep_nest.hpp"
#include "flow/seeds.hpp"
#include "flow/stored_traces.hpp"
#include "flow/vector_selection.hpp"
#include "gpu/gpu_tracer.hpp"
#include "gpu_test.hpp"
#include "random_amr.hpp"
#include "volume_options.hpp"

namespace amrstream::gpu {
namespace {

using flow::PointColumn;

constexpr PointColumn kColumns[] = {PointColumn::Positions, PointColumn::PositionsLow,
                                    PointColumn::Times,     PointColumn::Vectors,
                                    PointColumn::Channels,  PointColumn::Vorticity};

// Whether `line`'s `column` reads the same from both, bit for bit.
bool sameColumn(const flow::TraceView& device, const flow::TraceSet& host, PointColumn column,
                std::size_t line) {
  const flow::TraceSetView expected(host);
  std::vector<float> a, b;
  const std::span<const float> got = device.column(column, line, a);
  const std::span<const float> want = expected.column(column, line, b);
  return got.size() == want.size() &&
         std::equal(got.begin(), got.end(), want.begin(), [](float x, float y) {
           return std::bit_cast<std::uint32_t>(x) == std::bit_cast<std::uint32_t>(y);
         });
}

void expectSameTraces(const flow::TraceView& device, const flow::TraceSet& host) {
  const flow::TraceSet& lines = device.lines();
  ASSERT_EQ(lines.lineCount(), host.lineCount());
  EXPECT_EQ(lines.seedIds, host.seedIds);
  EXPECT_EQ(lines.directions, host.directions);
  EXPECT_EQ(lines.steps, host.steps);
  EXPECT_EQ(lines.reasons, host.reasons);
  EXPECT_EQ(lines.offsets, host.offsets);
  EXPECT_EQ(lines.precisePositions, host.precisePositions);
  EXPECT_EQ(lines.withVorticity, host.withVorticity);
  EXPECT_EQ(lines.channelNames, host.channelNames);
  for (const PointColumn column : kColumns) {
    for (std::size_t line = 0; line < host.lineCount(); ++line)
      ASSERT_TRUE(sameColumn(device, host, column, line))
          << "column " << int(column) << " line " << line << " in order";
    for (std::size_t line = host.lineCount(); line-- > 0;)
      ASSERT_TRUE(sameColumn(device, host, column, line))
          << "column " << int(column) << " line " << line << " backwards";
  }
  std::atomic<std::size_t> differing{0};
  tbb::parallel_for(std::size_t(0), host.lineCount() * std::size(kColumns), [&](std::size_t i) {
    const std::size_t line = (i * 7919) % host.lineCount();
    if (!sameColumn(device, host, kColumns[i % std::size(kColumns)], line)) ++differing;
  });
  EXPECT_EQ(differing.load(), 0u) << "read from many threads";
}

class DeviceTracesTest : public testing::GpuTest, public ::testing::WithParamInterface<Backend> {
 protected:
  vk::CapabilitySet required() const override { return requiredCapabilities(GetParam()); }
};

// Channels, vorticity and both directions, in batches of 7 lines and rounds of a few steps, read
// through windows of 100 bytes (8 vectors): every window ends inside a line or between two.
TEST_P(DeviceTracesTest, PointDataVorticityBatchesAndRoundsReadAsCollected) {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  const bricks::AmrField field = testing::randomAmr(5, layout, [](glm::dvec3 p) {
    return glm::vec3(0.3 + 0.02 * p.y, 0.2 * std::cos(0.3 * p.x), 0.1 + 0.01 * p.z);
  });
  const flow::VectorVolume volume = flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"},
                                                            testing::withPointData({"vy", "vx"}));
  flow::TraceOptions options;
  options.maxSteps = 300;
  options.vorticity = true;
  options.memoryBudget = 8 << 10;
  const glm::dvec3 lo = flow::domainLower(volume), hi = flow::domainUpper(volume);
  const flow::SeedList seeds = flow::randomSeedsInBox(lo, hi - 1e-3 * (hi - lo), 30, 3);

  GpuTracer tracer(ctx(), GetParam(), volume);
  tracer.limitLinesPerBatch(7);
  tracer.setTraceWindow(100);
  const flow::TraceSet host = tracer.trace(seeds.points, options);
  const std::unique_ptr<DeviceTraces> device = tracer.traceOnDevice(seeds.points, options);
  ASSERT_NE(device, nullptr);
  EXPECT_GT(tracer.lastRun().batches, 5u);
  EXPECT_GT(tracer.lastRun().rounds, 2 * tracer.lastRun().batches);
  EXPECT_GT(host.pointCount(), 10 * host.lineCount());
  // Position, time, vector, the two channels and the vorticity: each round's room is made before
  // its points are counted, for as many as it might emit.
  EXPECT_GE(device->deviceBytes(), host.pointCount() * (2 * 12 + 4 + 2 * 4 + 12));
  expectSameTraces(*device, host);
}

// Positions relative to their regions' corners come back split into high and low parts.
TEST_P(DeviceTracesTest, DeepPositionsReadAsCollected) {
  if (GetParam() == Backend::Pipeline) GTEST_SKIP() << "the pipeline backend refuses deep nests";
  const testing::DeepNest nest = testing::deepNest();
  const flow::VectorVolume volume =
      flow::buildVectorVolume(nest.field, flow::chooseVectorChannels(nest.field, ""));
  ASSERT_TRUE(volume.deepPositions());
  flow::TraceOptions options;
  options.stepMode = flow::StepMode::Time;
  options.stepSize = 1.0f / 128;
  options.maxSteps = 100;
  GpuTracer tracer(ctx(), GetParam(), volume);
  tracer.setTraceWindow(1000);
  const flow::TraceSet host = tracer.trace(nest.seeds, options);
  ASSERT_TRUE(host.precisePositions);
  const std::unique_ptr<DeviceTraces> device = tracer.traceOnDevice(nest.seeds, options);
  ASSERT_NE(device, nullptr);
  expectSameTraces(*device, host);
}

// The endpoints of thousands of lines through whole windows: runs of one point, thousands in a
// dispatch, copied a word per invocation.
TEST_P(DeviceTracesTest, EndpointsOfManyLinesReadAsCollected) {
  testing::RandomAmrOptions layout;
  layout.levels = 2;
  const bricks::AmrField field = testing::randomAmr(7, layout, [](glm::dvec3 p) {
    return glm::vec3(0.2 + 0.01 * p.z, 0.3 * std::sin(0.2 * p.x), 0.1);
  });
  const flow::VectorVolume volume = flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"});
  flow::TraceOptions options;
  options.maxSteps = 40;
  options.keepHistory = false;
  const glm::dvec3 lo = flow::domainLower(volume), hi = flow::domainUpper(volume);
  const flow::SeedList seeds = flow::randomSeedsInBox(lo, hi - 1e-3 * (hi - lo), 3000, 5);
  GpuTracer tracer(ctx(), GetParam(), volume);
  const flow::TraceSet host = tracer.trace(seeds.points, options);
  const std::unique_ptr<DeviceTraces> device = tracer.traceOnDevice(seeds.points, options);
  ASSERT_NE(device, nullptr);
  EXPECT_EQ(host.lineCount(), 6000u);
  EXPECT_LE(host.pointCount(), 2 * host.lineCount());
  expectSameTraces(*device, host);
}

// Once the tracer's volume is freed (as the command line does while it writes), the kept traces
// still read as collected, and the tracer refuses to trace.
TEST_P(DeviceTracesTest, KeptTracesOutliveTheVolumesDeviceBuffers) {
  const bricks::AmrField field = testing::randomAmr(
      3, {}, [](glm::dvec3 p) { return glm::vec3(0.3, 0.1 * std::sin(0.4 * p.x), 0.05); });
  const flow::VectorVolume volume = flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"});
  flow::TraceOptions options;
  options.maxSteps = 60;
  const glm::dvec3 lo = flow::domainLower(volume), hi = flow::domainUpper(volume);
  const flow::SeedList seeds = flow::randomSeedsInBox(lo, hi - 1e-3 * (hi - lo), 200, 9);
  GpuTracer tracer(ctx(), GetParam(), volume);
  tracer.setTraceWindow(400);
  const flow::TraceSet host = tracer.trace(seeds.points, options);
  const std::unique_ptr<DeviceTraces> device = tracer.traceOnDevice(seeds.points, options);
  ASSERT_NE(device, nullptr);
  { const VolumeBuffers freed = tracer.releaseVolume(); }
  expectSameTraces(*device, host);
  EXPECT_THROW(tracer.trace(seeds.points, options), std::logic_error);
  EXPECT_THROW(tracer.releaseVolume(), std::logic_error);
}

// Lines whose every step might not fit the device's memory stay on the host.
TEST_P(DeviceTracesTest, LinesThatMightNotFitAreNotKept) {
  const bricks::AmrField field =
      testing::randomAmr(2, {}, [](glm::dvec3) { return glm::vec3(1.0f, 0.0f, 0.0f); });
  const flow::VectorVolume volume = flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"});
  GpuTracer tracer(ctx(), GetParam(), volume);
  flow::TraceOptions options;
  options.maxSteps = 1'000'000'000;
  const std::vector<glm::dvec3> seeds(1000, flow::domainLower(volume) + 0.5);
  EXPECT_FALSE(tracer.fitsOnDevice(options, seeds.size() * 2));
  EXPECT_EQ(tracer.traceOnDevice(seeds, options), nullptr);
  options.keepHistory = false;  // one point a line
  EXPECT_TRUE(tracer.fitsOnDevice(options, seeds.size() * 2));
}

INSTANTIATE_TEST_SUITE_P(Backends, DeviceTracesTest,
                         ::testing::Values(Backend::RayQuery, Backend::Pipeline, Backend::Compute),
                         [](const auto& info) { return std::string(backendName(info.param)); });

}  // namespace
}  // namespace amrstream::gpu
