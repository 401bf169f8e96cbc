// Every GPU backend against the CPU reference: the same datasets, seeds and options must give
// the same point counts and termination reasons, and positions within a stated tolerance.

#include "gpu/gpu_tracer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "flow/integrator.hpp"
#include "flow/progressive_traces.hpp"
#include "flow/seeds.hpp"
#include "gpu_test.hpp"
#include "random_amr.hpp"
#include "synth/generators.hpp"

namespace amrstream::gpu {
namespace {

// Both paths evaluate the same float formulas in the same order, without FMA contraction (the
// kernels are `precise`). What remains is the precision Vulkan allows a GPU for division and
// square roots (2.5 and 3 ulp, where the CPU rounds correctly): a few ulp of a coordinate per
// step, about 2e-6 finest cells for coordinates up to 64 cells, adding up along the trace on these
// neutrally stable flows. So positions may differ by 1e-5 finest cells plus 2e-6 per step. On
// lavapipe the paths agree to better than 1e-4 after 300 steps; on an H200 to 1.004e-4 at step
// 298; a wrong RK4 stage (x + 0.51 k1) misses by orders of magnitude more.
double positionTolerance(std::uint32_t step) { return 1e-5 + 2e-6 * double(step); }

class GpuTracerTest : public testing::GpuTest, public ::testing::WithParamInterface<Backend> {
 protected:
  vk::CapabilitySet required() const override { return requiredCapabilities(GetParam()); }

  KernelSettings settings_ = defaultKernelSettings(GetParam());

  void compare(const flow::VectorVolume& volume, const flow::SeedList& seeds,
               const flow::TraceOptions& options, std::size_t seedsPerChunk = 0) {
    const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
    GpuTracer tracer(ctx(), GetParam(), volume, settings_);
    tracer.limitSeedsPerChunk(seedsPerChunk);
    const flow::TraceSet gpu = tracer.trace(seeds.points, options);
    ASSERT_EQ(gpu.seedCount, cpu.seedCount);
    ASSERT_EQ(gpu.capacity, cpu.capacity);
    const glm::dvec3 spacing = volume.transform.spacing;
    const double finestCell = std::min({spacing.x, spacing.y, spacing.z});
    std::size_t points = 0;
    for (std::uint32_t s = 0; s < cpu.seedCount; ++s) {
      ASSERT_EQ(gpu.reasons[s], cpu.reasons[s]) << "seed " << s;
      ASSERT_EQ(gpu.pointCounts[s], cpu.pointCounts[s]) << "seed " << s;
      ASSERT_EQ(gpu.steps[s], cpu.steps[s]) << "seed " << s;
      for (std::uint32_t p = 0; p < cpu.pointCounts[s]; ++p, ++points) {
        const std::size_t i = cpu.at(s, p);
        ASSERT_LE(glm::length(glm::dvec3(gpu.positions[i]) - glm::dvec3(cpu.positions[i])),
                  positionTolerance(p) * finestCell)
            << "seed " << s << " point " << p;
        ASSERT_NEAR(gpu.times[i], cpu.times[i], 1e-5f * std::max(1.0f, std::abs(cpu.times[i])));
        ASSERT_LE(glm::length(gpu.vectors[i] - cpu.vectors[i]),
                  1e-5f * std::max(1.0f, glm::length(cpu.vectors[i])));
      }
    }
    EXPECT_GT(points, cpu.seedCount) << "the traces should take steps";
  }

  static flow::SeedList seedsIn(const flow::VectorVolume& volume, std::size_t count) {
    const glm::dvec3 lo = flow::domainLower(volume), hi = flow::domainUpper(volume);
    return flow::randomSeedsInBox(lo, hi - 1e-3 * (hi - lo), count, 7);
  }
};

flow::VectorVolume volumeOf(const bricks::AmrField& field) {
  return flow::buildVectorVolume(field, flow::chooseVectorChannels(field, ""));
}

TEST_P(GpuTracerTest, MatchesCpuOnRotation) {
  const bricks::AmrField field = synth::generate("rotation", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  flow::TraceOptions options;
  options.maxSteps = 300;
  compare(volume, seedsIn(volume, 64), options);
}

TEST_P(GpuTracerTest, MatchesCpuOnAbcInEveryStepMode) {
  const bricks::AmrField field = synth::generate("abc", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  for (flow::StepMode mode : {flow::StepMode::Cell, flow::StepMode::Time, flow::StepMode::Arc}) {
    flow::TraceOptions options;
    options.stepMode = mode;
    options.stepSize = mode == flow::StepMode::Time ? 1e-3f : 0.25f;
    options.maxSteps = 200;
    SCOPED_TRACE(static_cast<int>(mode));
    compare(volume, seedsIn(volume, 48), options);
  }
}

TEST_P(GpuTracerTest, MatchesCpuOnRandomMultiLevelLayouts) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    testing::RandomAmrOptions layout;
    layout.levels = 4;
    layout.rootCells = glm::ivec3(4, 3, 3);
    const glm::dvec3 centre(16.0, 12.0, 12.0);
    const bricks::AmrField field = testing::randomAmr(seed, layout, [&](glm::dvec3 p) {
      const glm::dvec3 r = p - centre;  // a rotation with a slow drift along z
      return glm::vec3(-0.05 * r.y, 0.05 * r.x, 0.02);
    });
    const flow::VectorVolume volume = volumeOf(field);
    flow::TraceOptions options;
    options.maxSteps = 300;
    SCOPED_TRACE(seed);
    compare(volume, seedsIn(volume, 64), options);
  }
}

// The region hint, on and off (each backend's default is one of them): the same traces.
TEST_P(GpuTracerTest, WithAndWithoutTheRegionHintMatchesCpu) {
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  const glm::dvec3 centre(16.0, 16.0, 16.0);
  const bricks::AmrField field = testing::randomAmr(5, layout, [&](glm::dvec3 p) {
    const glm::dvec3 r = p - centre;
    return glm::vec3(-0.05 * r.y, 0.05 * r.x, 0.02);
  });
  const flow::VectorVolume volume = volumeOf(field);
  flow::TraceOptions options;
  options.maxSteps = 200;
  for (const bool hint : {false, true}) {
    SCOPED_TRACE(hint ? "with the hint" : "without the hint");
    settings_.useRegionHint = hint;
    compare(volume, seedsIn(volume, 48), options);
  }
}

TEST_P(GpuTracerTest, MatchesCpuOnEveryTerminationReason) {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  const bricks::AmrField field = testing::randomAmr(9, layout, [](glm::dvec3 p) {
    return glm::vec3(1.0 - p.x / 12.0, 0.1, 0.0);  // slows down towards x = 12, stops there
  });
  const flow::VectorVolume volume = volumeOf(field);
  flow::TraceOptions options;
  options.maxSteps = 120;
  options.terminalSpeed = 0.2f;  // stagnation near x = 9.6
  options.maxLength = 30.0f;
  compare(volume, seedsIn(volume, 96), options);
}

TEST_P(GpuTracerTest, EndpointsOnlyMatchesCpu) {
  const bricks::AmrField field = synth::generate("abc", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  const flow::SeedList seeds = seedsIn(volume, 64);
  flow::TraceOptions options;
  options.maxSteps = 300;
  options.keepHistory = false;
  const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
  GpuTracer tracer(ctx(), GetParam(), volume);
  const flow::TraceSet gpu = tracer.trace(seeds.points, options);
  ASSERT_EQ(gpu.capacity, 1u);
  const double finestCell = std::min(
      {volume.transform.spacing.x, volume.transform.spacing.y, volume.transform.spacing.z});
  for (std::uint32_t s = 0; s < cpu.seedCount; ++s) {
    ASSERT_EQ(gpu.pointCounts[s], 1u);
    ASSERT_EQ(gpu.steps[s], cpu.steps[s]) << "seed " << s;
    ASSERT_EQ(gpu.reasons[s], cpu.reasons[s]) << "seed " << s;
    EXPECT_LE(glm::length(glm::dvec3(gpu.positions[s]) - glm::dvec3(cpu.positions[s])),
              positionTolerance(cpu.steps[s]) * finestCell)
        << "seed " << s;
  }
}

// The viewer's progressive tracing: traces grown 13 steps per round on the GPU equal the CPU's
// one run.
TEST_P(GpuTracerTest, ProgressiveRoundsMatchOneCpuRun) {
  const bricks::AmrField field = synth::generate("abc", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  const flow::SeedList seeds = seedsIn(volume, 48);
  flow::TraceOptions options;
  options.maxSteps = 100;
  const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  flow::ProgressiveTraces grown(seeds.points, options, volume.vectorName);
  const flow::TraceFunction gpuTrace = [&](std::span<const glm::dvec3> starts,
                                           const flow::TraceOptions& o) {
    return tracer.trace(starts, o);
  };
  while (!grown.finished()) grown.advance(gpuTrace, 13);
  const flow::TraceSet& gpu = grown.traces();
  const double finestCell = volume.transform.spacing.x;
  for (std::uint32_t s = 0; s < cpu.seedCount; ++s) {
    ASSERT_EQ(gpu.reasons[s], cpu.reasons[s]) << "seed " << s;
    ASSERT_EQ(gpu.pointCounts[s], cpu.pointCounts[s]) << "seed " << s;
    for (std::uint32_t p = 0; p < cpu.pointCounts[s]; ++p)
      ASSERT_LE(glm::length(glm::dvec3(gpu.positions[gpu.at(s, p)]) -
                            glm::dvec3(cpu.positions[cpu.at(s, p)])),
                (positionTolerance(p) + 1e-4) * finestCell)
          << "seed " << s << " point " << p;
  }
}

// Threads take seeds in Morton order by default; the traces, returned in the caller's order, are
// the same bit for bit as with seeds in the given order (each thread's work does not depend on
// its neighbours).
TEST_P(GpuTracerTest, SpatialSeedOrderGivesTheSameTraces) {
  const bricks::AmrField field = synth::generate("abc", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  const flow::SeedList seeds = seedsIn(volume, 200);
  flow::TraceOptions options;
  options.maxSteps = 60;
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  const flow::TraceSet spatial = tracer.trace(seeds.points, options);
  tracer.orderSeedsSpatially(false);
  const flow::TraceSet given = tracer.trace(seeds.points, options);
  EXPECT_EQ(spatial.pointCounts, given.pointCounts);
  EXPECT_EQ(spatial.reasons, given.reasons);
  EXPECT_EQ(spatial.positions, given.positions);
  EXPECT_EQ(spatial.times, given.times);
  EXPECT_EQ(spatial.vectors, given.vectors);
}

TEST_P(GpuTracerTest, ChunksOfSeedsGiveTheSameTraces) {
  const bricks::AmrField field = synth::generate("rotation", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  flow::TraceOptions options;
  options.maxSteps = 100;
  compare(volume, seedsIn(volume, 50), options, 7);  // 8 dispatches, the last one of 1 seed
}

TEST_P(GpuTracerTest, ChunkSizeRespectsTheStorageBufferRange) {
  const bricks::AmrField field = synth::generate("rotation", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  GpuTracer tracer(ctx(), GetParam(), volume);
  flow::TraceOptions options;
  options.maxSteps = 20;
  const std::size_t chunk = tracer.seedsPerChunk(options.maxSteps + 1);
  EXPECT_GT(chunk, 0u);
  EXPECT_LE(chunk * (options.maxSteps + 1) * sizeof(glm::vec3),
            ctx().limits().maxStorageBufferRange);
}

// The run statistics the benchmark reports: kernel time from timestamps (positive and within
// the wall time of the run), one chunk per dispatch, and device bytes that add up.
TEST_P(GpuTracerTest, ReportsKernelTimeChunksAndDeviceBytes) {
  const bricks::AmrField field = synth::generate("rotation", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  GpuTracer tracer(ctx(), GetParam(), volume);
  const TracerSetup& setup = tracer.setup();
  EXPECT_EQ(setup.volumeBytes, volume.bricks.size() * sizeof(shared::Brick) +
                                   volume.values.size() * sizeof(glm::vec3) +
                                   volume.regions.regions.size() * sizeof(shared::Region) +
                                   volume.regions.regionBricks.size() * sizeof(std::uint32_t));
  if (GetParam() == Backend::Compute)
    EXPECT_EQ(setup.structureBytes, volume.regions.tree.size() * sizeof(shared::RegionTreeNode));
  else
    EXPECT_GT(setup.structureBytes, volume.regions.regions.size() * sizeof(VkAabbPositionsKHR) / 2);

  flow::TraceOptions options;
  options.maxSteps = 200;
  const flow::SeedList seeds = seedsIn(volume, 40);
  tracer.limitSeedsPerChunk(16);
  const auto start = std::chrono::steady_clock::now();
  tracer.trace(seeds.points, options);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const TraceRunStats& run = tracer.lastRun();
  EXPECT_EQ(run.chunks, 3u);
  EXPECT_EQ(run.chunkBytes, 16 * (sizeof(glm::vec3) + 201 * flow::TraceSet::kBytesPerPoint +
                                  sizeof(std::uint32_t) + sizeof(std::int32_t)));
  ASSERT_TRUE(run.kernelSeconds.has_value()) << "lavapipe and NVIDIA have compute timestamps";
  EXPECT_GT(*run.kernelSeconds, 0.0);
  EXPECT_LT(*run.kernelSeconds, wall);
}

INSTANTIATE_TEST_SUITE_P(Backends, GpuTracerTest,
                         ::testing::Values(Backend::RayQuery, Backend::Pipeline, Backend::Compute),
                         [](const auto& info) { return std::string(backendName(info.param)); });

}  // namespace
}  // namespace amrstream::gpu
