// Every GPU backend against the CPU reference: the same datasets, seeds and options must give
// the same point counts and termination reasons, and positions within a stated tolerance.

#include "gpu/gpu_tracer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>

#include "bricks/descent_tree.hpp"
#include "flow/cpu_tracer.hpp"
#include "flow/line_plan.hpp"
#include "flow/progressive_traces.hpp"
#include "flow/sampler.hpp"
#include "flow/seeds.hpp"
#include "gpu_test.hpp"
#include "random_amr.hpp"
#include "synth/generators.hpp"
#include "volume_options.hpp"

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

// Lines, counts, steps and reasons exactly; every point's position within the tolerance for its
// index along its line. The data at a point (vector, channels, vorticity) is checked against the
// CPU's reconstruction at the GPU's own position: positions may drift apart within their
// tolerance, and the field changes with them, but the GPU's sampler must agree with the CPU's
// where it sampled.
void expectGpuMatchesCpu(const flow::TraceSet& gpu, const flow::TraceSet& cpu,
                         const flow::VectorVolume& volume) {
  ASSERT_EQ(gpu.lineCount(), cpu.lineCount());
  ASSERT_EQ(gpu.seedIds, cpu.seedIds);
  ASSERT_EQ(gpu.directions, cpu.directions);
  ASSERT_EQ(gpu.channelNames, cpu.channelNames);
  ASSERT_EQ(gpu.withVorticity, cpu.withVorticity);
  const glm::dvec3 spacing = volume.transform.spacing;
  const double finestCell = std::min({spacing.x, spacing.y, spacing.z});
  const std::size_t channels = cpu.channelCount();
  const auto close = [](float a, float b, float relative) {
    return (std::isnan(a) && std::isnan(b)) ||
           std::abs(a - b) <= relative * std::max(1.0f, std::abs(b));
  };
  std::vector<float> expectedChannels(channels);
  for (std::size_t line = 0; line < cpu.lineCount(); ++line) {
    ASSERT_EQ(gpu.reasons[line], cpu.reasons[line]) << "line " << line;
    ASSERT_EQ(gpu.steps[line], cpu.steps[line]) << "line " << line;
    ASSERT_EQ(gpu.pointCount(line), cpu.pointCount(line)) << "line " << line;
    for (std::uint64_t k = 0; k < cpu.pointCount(line); ++k) {
      const std::uint64_t i = cpu.firstPoint(line) + k;
      const std::uint32_t step = cpu.steps[line] + 1 == cpu.pointCount(line)
                                     ? std::uint32_t(k)
                                     : cpu.steps[line];  // endpoints: the last step
      ASSERT_LE(glm::length(glm::dvec3(gpu.positions[i]) - glm::dvec3(cpu.positions[i])),
                positionTolerance(step) * finestCell)
          << "line " << line << " point " << k;
      ASSERT_TRUE(close(gpu.times[i], cpu.times[i], 1e-5f)) << "line " << line << " point " << k;

      const glm::vec3 at(volume.transform.toCellUnits(glm::dvec3(gpu.positions[i])));
      const flow::VectorSample sample = flow::sampleVector(volume, at);
      ASSERT_TRUE(sample.valid) << "line " << line << " point " << k;
      ASSERT_LE(glm::length(gpu.vectors[i] - sample.value),
                1e-5f * std::max(1.0f, glm::length(sample.value)))
          << "line " << line << " point " << k;
      flow::sampleChannels(volume, sample.region, at, expectedChannels);
      for (std::size_t c = 0; c < channels; ++c)
        ASSERT_TRUE(close(gpu.channels[i * channels + c], expectedChannels[c], 1e-4f))
            << "line " << line << " point " << k << " channel " << cpu.channelNames[c] << ": "
            << gpu.channels[i * channels + c] << " vs " << expectedChannels[c];
      if (cpu.withVorticity) {
        const glm::vec3 expected = flow::sampleVorticity(volume, sample.region, at);
        for (int c = 0; c < 3; ++c)
          ASSERT_TRUE(close(gpu.vorticity[i][c], expected[c], 1e-4f))
              << "line " << line << " point " << k << " vorticity " << c;
      }
    }
  }
  EXPECT_GT(cpu.pointCount(), 2 * cpu.lineCount()) << "the traces should take steps";
}

// Endpoints only: one point a line, the CPU's steps and reasons exactly, each line's last point
// within the tolerance for its steps.
void expectEndpointsMatchCpu(const flow::TraceSet& gpu, const flow::TraceSet& cpu,
                             const flow::VectorVolume& volume) {
  for (std::size_t line = 0; line < cpu.lineCount(); ++line) ASSERT_EQ(gpu.pointCount(line), 1u);
  ASSERT_EQ(gpu.steps, cpu.steps);
  ASSERT_EQ(gpu.reasons, cpu.reasons);
  const double finestCell = volume.transform.spacing.x;
  for (std::size_t line = 0; line < cpu.lineCount(); ++line)
    EXPECT_LE(glm::length(glm::dvec3(gpu.positions[line]) - glm::dvec3(cpu.positions[line])),
              positionTolerance(cpu.steps[line]) * finestCell)
        << "line " << line;
}

// Two GPU traces that must be the same bit for bit.
void expectSameTraces(const flow::TraceSet& a, const flow::TraceSet& b) {
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.reasons, b.reasons);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.times, b.times);
  EXPECT_EQ(a.vectors, b.vectors);
}

class GpuTracerTest : public testing::GpuTest, public ::testing::WithParamInterface<Backend> {
 protected:
  vk::CapabilitySet required() const override { return requiredCapabilities(GetParam()); }

  KernelSettings settings_ = defaultKernelSettings(GetParam());

  void compare(const flow::VectorVolume& volume, const flow::SeedList& seeds,
               const flow::TraceOptions& options, std::size_t linesPerBatch = 0,
               std::uint64_t stagingSlotBytes = 0) {
    const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
    GpuTracer tracer(ctx(), GetParam(), volume, settings_);
    tracer.limitLinesPerBatch(linesPerBatch);
    if (stagingSlotBytes > 0) tracer.setStaging(2, stagingSlotBytes);
    expectGpuMatchesCpu(tracer.trace(seeds.points, options), cpu, volume);
  }

  static flow::SeedList seedsIn(const flow::VectorVolume& volume, std::size_t count) {
    const glm::dvec3 lo = flow::domainLower(volume), hi = flow::domainUpper(volume);
    return flow::randomSeedsInBox(lo, hi - 1e-3 * (hi - lo), count, 7);
  }
};

flow::VectorVolume volumeOf(const bricks::AmrField& field, flow::VolumeOptions options = {}) {
  return flow::buildVectorVolume(field, flow::chooseVectorChannels(field, ""), options);
}

// A random four-level layout of a rotation about the axis x = y = 16, moving along it at
// `axial` + `growth` (z - 16).
bricks::AmrField rotationAboutZ(double axial, double growth) {
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  const glm::dvec3 centre(16.0, 16.0, 16.0);
  return testing::randomAmr(5, layout, [=](glm::dvec3 p) {
    const glm::dvec3 r = p - centre;
    return glm::vec3(-0.05 * r.y, 0.05 * r.x, axial + growth * r.z);
  });
}

TEST_P(GpuTracerTest, MatchesCpuOnRotationInBothDirections) {
  const bricks::AmrField field = synth::generate("rotation", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  flow::TraceOptions options;
  options.maxSteps = 300;
  compare(volume, seedsIn(volume, 64), options);
}

TEST_P(GpuTracerTest, MatchesCpuOnAbcInEveryStepModeAndDirection) {
  const bricks::AmrField field = synth::generate("abc", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  for (flow::StepMode mode : {flow::StepMode::Cell, flow::StepMode::Time, flow::StepMode::Arc}) {
    flow::TraceOptions options;
    options.stepMode = mode;
    options.stepSize = mode == flow::StepMode::Time ? 1e-3f : 0.25f;
    options.maxSteps = 200;
    options.direction =
        mode == flow::StepMode::Arc ? flow::Direction::Backward : flow::Direction::Both;
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
  const flow::VectorVolume volume = volumeOf(rotationAboutZ(0.02, 0.0));
  flow::TraceOptions options;
  options.maxSteps = 200;
  for (const bool hint : {false, true}) {
    SCOPED_TRACE(hint ? "with the hint" : "without the hint");
    settings_.useRegionHint = hint;
    compare(volume, seedsIn(volume, 48), options);
  }
}

// Dual cells (VolumeBuffers::dualValues) hold the same values in another order, and the kernel
// sums them in the same order: traces bit for bit those of the compact layout, and the CPU's
// within the tolerance, on a random multi-level layout made periodic (so that image bricks, which
// get dual cells of their own, are read too).
TEST_P(GpuTracerTest, DualValuesTraceAsTheCompactLayout) {
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  layout.rootCells = glm::ivec3(4, 3, 3);
  const double pi = std::numbers::pi;
  const auto flowAt = [&](glm::dvec3 p) {
    return glm::vec3(0.8, 0.5 * std::sin(2.0 * pi * p.x / 16.0),
                     0.4 * std::cos(2.0 * pi * p.y / 12.0) + 0.3);
  };
  const flow::VectorVolume volume =
      flow::buildVectorVolume(testing::randomAmr(6, layout, flowAt), {{"vx", "vy", "vz"}, "v"},
                              testing::periodicVolume(flow::PeriodicAxes{true, true, true}));
  flow::TraceOptions options;
  options.maxSteps = 200;
  const flow::SeedList seeds = seedsIn(volume, 48);
  std::array<flow::TraceSet, 2> traces;
  for (const bool dual : {false, true}) {
    KernelSettings settings = settings_;
    settings.dualValues = dual;
    GpuTracer tracer(ctx(), GetParam(), volume, settings);
    ASSERT_EQ(tracer.settings().dualValues, dual);
    ASSERT_EQ(tracer.volumeBuffers().dualValues.size() > 0, dual);
    traces[dual] = tracer.trace(seeds.points, options);
  }
  expectSameTraces(traces[1], traces[0]);
  expectGpuMatchesCpu(traces[1], flow::traceStreamlines(volume, seeds.points, options), volume);
}

// Dual cells are laid out for a run only where it takes enough steps per byte of them: 10 for
// the compute kernels, half a step for the ray tracing pipeline, whose samples gain more.
TEST(RunKernelSettingsTest, DualCellsOnlyWhereTheRunsStepsPayForThem) {
  const flow::VectorVolume volume = volumeOf(rotationAboutZ(0.02, 0.0));
  const double bytes = double(VolumeBuffers::dualValueBytes(volume));
  ASSERT_GT(bytes, 0.0);
  const auto dualFor = [&](Backend backend, double stepsPerByte) {
    return runKernelSettings(backend, volume, std::uint64_t(stepsPerByte * bytes)).dualValues;
  };
  for (const Backend backend : {Backend::Compute, Backend::RayQuery}) {
    EXPECT_EQ(dualFor(backend, 0.0), false);
    EXPECT_EQ(dualFor(backend, 0.6), false);
    EXPECT_EQ(dualFor(backend, 9.0), false);
    EXPECT_EQ(dualFor(backend, 11.0), std::nullopt);  // the device's default
  }
  EXPECT_EQ(dualFor(Backend::Pipeline, 0.4), false);
  EXPECT_EQ(dualFor(Backend::Pipeline, 0.6), std::nullopt);
}

// RK4's samples in one loop (the default on CPU devices such as lavapipe) or written out (on
// GPUs): the same sums in the same order, so the same traces bit for bit, with dual cells as GPUs
// read them and steps shortened to end on --max-time.
TEST_P(GpuTracerTest, Rk4SampleLoopTracesAsTheWrittenOutStep) {
  if (GetParam() == Backend::Pipeline) GTEST_SKIP() << "the pipeline kernel always loops";
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  const bricks::AmrField field = testing::randomAmr(
      11, layout, [](glm::dvec3 p) { return glm::vec3(0.6 - 0.05 * p.y, 0.3 + 0.04 * p.x, 0.2); });
  const flow::VectorVolume volume = volumeOf(field);
  flow::TraceOptions options;
  options.maxSteps = 150;
  options.stepMode = flow::StepMode::Time;
  options.stepSize = 0.3f;
  options.maxTime = 20.0f;
  const flow::SeedList seeds = seedsIn(volume, 40);
  std::array<flow::TraceSet, 2> traces;
  for (const bool loop : {false, true}) {
    KernelSettings settings = settings_;
    settings.rk4SampleLoop = loop;
    settings.dualValues = true;
    GpuTracer tracer(ctx(), GetParam(), volume, settings);
    ASSERT_EQ(tracer.settings().rk4SampleLoop, loop);
    traces[loop] = tracer.trace(seeds.points, options);
  }
  expectSameTraces(traces[1], traces[0]);
  expectGpuMatchesCpu(traces[0], flow::traceStreamlines(volume, seeds.points, options), volume);
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
  options.maxLength = 0.0f;
  options.maxTime = 9.0f;  // the last step shortened
  options.stepMode = flow::StepMode::Time;
  options.stepSize = 0.4f;
  compare(volume, seedsIn(volume, 96), options);
}

// The tolerance grows linearly with the step, as rounding differences do on neutrally stable
// flows (rotations); on the chaotic ABC flow they grow exponentially, so long comparisons use
// rotations (on an H200 a backward ABC line differed by 5e-4 finest cells after 45 steps).
TEST_P(GpuTracerTest, EndpointsOnlyMatchesCpu) {
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  layout.rootCells = glm::ivec3(4, 3, 3);
  const glm::dvec3 centre(16.0, 12.0, 12.0);
  const bricks::AmrField field = testing::randomAmr(2, layout, [&](glm::dvec3 p) {
    const glm::dvec3 r = p - centre;
    return glm::vec3(-0.05 * r.y, 0.05 * r.x, 0.02);
  });
  const flow::VectorVolume volume = volumeOf(field);
  flow::TraceOptions options;
  options.maxSteps = 300;
  options.keepHistory = false;
  const flow::SeedList seeds = seedsIn(volume, 64);
  const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  expectEndpointsMatchCpu(tracer.trace(seeds.points, options), cpu, volume);
}

// A random four-level layout with a smooth vector and `extra` scalar channels s0, s1, ...,
// under a transform that is not the identity.
bricks::AmrField layoutWithChannels(int extra) {
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  const bricks::AmrField cells = testing::randomAmr(12, layout, [](glm::dvec3 p) {
    return glm::vec3(0.2 + 0.01 * p.y, 0.1 * std::cos(0.2 * p.x), 0.05 + 0.01 * p.z);
  });
  std::vector<Channel> channels = cells.channels();
  for (int c = 0; c < extra; ++c) {
    Channel channel{"s" + std::to_string(c), {}};
    for (std::size_t i = 0; i < cells.cellCount(); ++i)
      channel.values.push_back(float(std::sin(0.1 * double(i) + c)));
    channels.push_back(channel);
  }
  return bricks::AmrField({cells.lowers().begin(), cells.lowers().end()},
                          {cells.levels().begin(), cells.levels().end()}, channels,
                          {{1.0, 2.0, 3.0}, {0.5, 0.25, 0.5}}, "with channels");
}

// Point data: several channels (more than one group of four in the kernel) and the vorticity.
TEST_P(GpuTracerTest, PointDataAndVorticityMatchCpu) {
  const flow::VectorVolume volume =
      flow::buildVectorVolume(layoutWithChannels(3), {{"vx", "vy", "vz"}, "v"},
                              testing::withPointData({"s0", "vy", "s1", "vx", "s2"}));
  flow::TraceOptions options;
  options.maxSteps = 150;
  options.vorticity = true;
  compare(volume, seedsIn(volume, 40), options);
  // Through a staging ring of two 1000-byte slots (a dozen points each) as well.
  compare(volume, seedsIn(volume, 40), options, 0, 1000);
}

// The linear interpolant (vector, point data and vorticity) on a random four-level layout, and
// on a periodic one, equals the CPU's as the tent interpolant does.
TEST_P(GpuTracerTest, LinearInterpolantMatchesCpu) {
  flow::VolumeOptions volumeOptions = testing::withPointData({"s0", "vy"});
  volumeOptions.interpolant = flow::Interpolant::Linear;
  const flow::VectorVolume volume =
      flow::buildVectorVolume(layoutWithChannels(1), {{"vx", "vy", "vz"}, "v"}, volumeOptions);
  flow::TraceOptions options;
  options.maxSteps = 150;
  options.vorticity = true;
  compare(volume, seedsIn(volume, 40), options);

  flow::VolumeOptions periodic = testing::periodicVolume(flow::PeriodicAxes{true, true, true});
  periodic.interpolant = flow::Interpolant::Linear;
  testing::RandomAmrOptions small;
  small.levels = 3;
  const double pi = std::numbers::pi;
  const flow::VectorVolume wrapped = flow::buildVectorVolume(
      testing::randomAmr(
          4, small,
          [&](glm::dvec3 p) { return glm::vec3(0.8, 0.5 * std::sin(2.0 * pi * p.x / 12.0), 0.3); }),
      {{"vx", "vy", "vz"}, "v"}, periodic);
  options.vorticity = false;
  compare(wrapped, seedsIn(wrapped, 32), options);
}

// A periodic flow that crosses every face and is not chaotic (x drives y, y drives z), on a random
// multi-level layout: the tolerance that grows with the step holds (the chaotic ABC flow's
// differences outgrow it within 100 steps on an H200).
TEST_P(GpuTracerTest, PeriodicFlowMatchesCpuAcrossEveryFace) {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  layout.rootCells = glm::ivec3(3, 3, 3);  // 12 finest cells per axis
  const double pi = std::numbers::pi;
  const bricks::AmrField field = testing::randomAmr(4, layout, [&](glm::dvec3 p) {
    return glm::vec3(0.8, 0.5 * std::sin(2.0 * pi * p.x / 12.0),
                     0.4 * std::cos(2.0 * pi * p.y / 12.0) + 0.3);
  });
  const flow::VectorVolume volume =
      flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"},
                              testing::periodicVolume(flow::PeriodicAxes{true, true, true}));
  flow::TraceOptions options;
  options.maxSteps = 400;
  const flow::SeedList seeds = seedsIn(volume, 32);
  const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
  std::array<std::size_t, 3> wraps{};
  for (std::size_t line = 0; line < cpu.lineCount(); ++line) {
    EXPECT_EQ(cpu.reasons[line], AMRSTREAM_REASON_MAX_STEPS);
    for (std::uint64_t i = cpu.firstPoint(line) + 1; i < cpu.offsets[line + 1]; ++i)
      for (int a = 0; a < 3; ++a)
        wraps[a] += std::abs(cpu.positions[i][a] - cpu.positions[i - 1][a]) > 6.0f;
  }
  for (int a = 0; a < 3; ++a) EXPECT_GT(wraps[a], 5u) << "axis " << a;
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  // Positions are compared as they are stored, wrapped: a point that the two paths place on
  // opposite sides of a face within the tolerance would differ by a period, and fail.
  expectGpuMatchesCpu(tracer.trace(seeds.points, options), cpu, volume);
}

// Streamed history: lines of 1e5 steps in rounds of a few thousand steps, through a budget of
// 2 MiB, equal the GPU's own one run bit for bit, and the CPU's within the tolerance. In `time`
// mode: in `cell` mode a step's stages scale with the finest cell width of their regions, so a
// rounding difference that moves a stage point across a region face changes that step by a good
// part of itself, which over 1e5 steps happens (on an H200, 0.025 cells at step 5331).
TEST_P(GpuTracerTest, LongLinesStreamedInRoundsMatchCpu) {
  const glm::dvec3 centre(12.0, 12.0, 4.0);
  testing::RandomAmrOptions layout;
  layout.levels = 2;
  layout.rootCells = glm::ivec3(12, 12, 4);
  const bricks::AmrField field = testing::randomAmr(
      3, layout, [&](glm::dvec3 p) { return glm::vec3(-(p.y - centre.y), p.x - centre.x, 0.0); });
  const flow::VectorVolume volume = volumeOf(field);
  const std::vector<glm::dvec3> seeds{{17.0, 12.0, 4.1}, {12.0, 4.5, 2.0}, {15.0, 15.0, 6.0}};
  flow::TraceOptions options;
  options.maxSteps = 100000;
  options.stepMode = flow::StepMode::Time;
  options.stepSize = 0.02f;  // 0.15 cells at radius 7.5
  options.direction = flow::Direction::Forward;
  const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds, options);
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  const flow::TraceSet once = tracer.trace(seeds, options);
  EXPECT_EQ(tracer.lastRun().rounds, 1u);
  options.memoryBudget = 1 << 20;
  const flow::TraceSet gpu = tracer.trace(seeds, options);
  EXPECT_GT(tracer.lastRun().rounds, 10u);
  expectSameTraces(gpu, once);
  expectGpuMatchesCpu(gpu, cpu, volume);

  // Through a staging ring of three slots of 4000 bytes (125 points, the last piece of a round
  // partly filled), every round comes back in many pieces, three in flight.
  tracer.setStaging(3, 4000);
  expectSameTraces(tracer.trace(seeds, options), once);
}

// Every integrator (rk4 is the rest of this suite), in every step mode and both directions, with
// history and endpoints only, and rk45's last step landing on --max-time.
TEST_P(GpuTracerTest, EveryIntegratorMatchesCpu) {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  layout.rootCells = glm::ivec3(4, 3, 3);
  const glm::dvec3 centre(16.0, 12.0, 12.0);
  const bricks::AmrField field = testing::randomAmr(5, layout, [&](glm::dvec3 p) {
    const glm::dvec3 r = p - centre;  // a rotation with a slow drift along z
    return glm::vec3(-0.05 * r.y, 0.05 * r.x, 0.02);
  });
  const flow::VectorVolume volume = volumeOf(field);
  // Every step mode for rk45, whose step sizes depend on it; one for the fixed steps, whose
  // stage vectors are rk4's (lavapipe compiles a ray tracing pipeline with rk45 in minutes when
  // its shader cache is cold).
  const std::vector<std::pair<flow::Integrator, flow::StepMode>> cases{
      {flow::Integrator::Euler, flow::StepMode::Cell},
      {flow::Integrator::Rk2, flow::StepMode::Arc},
      {flow::Integrator::Rk45, flow::StepMode::Cell},
      {flow::Integrator::Rk45, flow::StepMode::Time},
      {flow::Integrator::Rk45, flow::StepMode::Arc}};
  for (const auto& [integrator, mode] : cases) {
    {
      flow::TraceOptions options;
      options.integrator = integrator;
      options.stepMode = mode;
      options.stepSize = mode == flow::StepMode::Time ? 2.0f : 0.25f;
      options.minStep = options.stepSize / 100.0f;
      options.maxStep = options.stepSize * 4.0f;
      options.tolerance = 1e-4f;
      options.maxSteps = 60;
      SCOPED_TRACE(static_cast<int>(integrator) * 10 + static_cast<int>(mode));
      compare(volume, seedsIn(volume, 24), options);
    }
  }
  flow::TraceOptions options;
  options.integrator = flow::Integrator::Rk45;
  options.stepMode = flow::StepMode::Time;
  options.stepSize = 1.0f;
  options.minStep = 0.01f;
  options.maxStep = 4.0f;
  options.maxTime = 37.3f;
  compare(volume, seedsIn(volume, 24), options);

  options.keepHistory = false;
  const flow::SeedList seeds = seedsIn(volume, 24);
  const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  const flow::TraceSet gpu = tracer.trace(seeds.points, options);
  expectEndpointsMatchCpu(gpu, cpu, volume);
  EXPECT_EQ(gpu.times, cpu.times);
}

// rk45 carries its next step from round to round: many short rounds equal one long one.
TEST_P(GpuTracerTest, Rk45StreamedInRoundsMatchesOneRound) {
  testing::RandomAmrOptions layout;
  layout.levels = 2;
  layout.rootCells = glm::ivec3(12, 12, 4);
  const glm::dvec3 centre(12.0, 12.0, 4.0);
  const bricks::AmrField field = testing::randomAmr(
      3, layout, [&](glm::dvec3 p) { return glm::vec3(-(p.y - centre.y), p.x - centre.x, 0.0); });
  const flow::VectorVolume volume = volumeOf(field);
  const std::vector<glm::dvec3> seeds{{17.0, 12.0, 4.1}, {12.0, 4.5, 2.0}, {15.0, 15.0, 6.0}};
  flow::TraceOptions options;
  options.integrator = flow::Integrator::Rk45;
  options.maxSteps = 1500;
  options.stepMode = flow::StepMode::Time;
  options.stepSize = 0.02f;
  options.minStep = 0.0002f;
  options.maxStep = 0.5f;
  options.direction = flow::Direction::Forward;
  const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds, options);
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  const flow::TraceSet once = tracer.trace(seeds, options);
  options.roundSteps = 7;
  const flow::TraceSet gpu = tracer.trace(seeds, options);
  EXPECT_GT(tracer.lastRun().rounds, 10u);
  EXPECT_EQ(gpu.positions, once.positions);
  EXPECT_EQ(gpu.times, once.times);
  expectGpuMatchesCpu(gpu, cpu, volume);
}

// The viewer's progressive tracing: lines grown 13 steps per round on the GPU equal the CPU's
// one run.
TEST_P(GpuTracerTest, ProgressiveRoundsMatchOneCpuRun) {
  const bricks::AmrField field = synth::generate("abc", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  const flow::SeedList seeds = seedsIn(volume, 48);
  flow::TraceOptions options;
  options.maxSteps = 100;
  const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  flow::LinePlan plan = flow::planLines(volume, seeds.points, options.direction);
  flow::ProgressiveTraces grown(tracer.startRounds(plan.states, options, 13), plan.layout,
                                flow::traceShape(volume, options));
  std::size_t rounds = 0;
  while (!grown.finished()) {
    grown.advance(13);
    ++rounds;
  }
  EXPECT_EQ(rounds, 8u);  // ceil(100 / 13)
  expectGpuMatchesCpu(grown.traces(), cpu, volume);
}

// Threads take lines in Morton order by default; the traces, returned in line order, are the
// same bit for bit as with lines in the given order (each thread's work does not depend on its
// neighbours).
TEST_P(GpuTracerTest, SpatialSeedOrderGivesTheSameTraces) {
  const bricks::AmrField field = synth::generate("abc", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  const flow::SeedList seeds = seedsIn(volume, 200);
  flow::TraceOptions options;
  options.maxSteps = 60;
  GpuTracer tracer(ctx(), GetParam(), volume, settings_);
  const flow::TraceSet spatial = tracer.trace(seeds.points, options);
  tracer.orderSeedsSpatially(false);
  expectSameTraces(spatial, tracer.trace(seeds.points, options));
}

TEST_P(GpuTracerTest, BatchesOfLinesGiveTheSameTraces) {
  const bricks::AmrField field = synth::generate("rotation", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  flow::TraceOptions options;
  options.maxSteps = 100;
  compare(volume, seedsIn(volume, 50), options, 7);  // 100 lines: 15 batches, the last of 2
}

TEST_P(GpuTracerTest, BatchesRespectTheStorageBufferRange) {
  const bricks::AmrField field = synth::generate("rotation", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  GpuTracer tracer(ctx(), GetParam(), volume);
  flow::TraceOptions options;
  options.memoryBudget = std::uint64_t(1) << 40;  // far more than any range
  const std::size_t batch = tracer.linesPerBatch(options, std::size_t(1) << 34);
  EXPECT_GT(batch, 0u);
  EXPECT_LE(batch * 2 * sizeof(glm::vec3), ctx().limits().maxStorageBufferRange);
}

// Rounds of few lines give each line up to 32 invocations (KernelSettings::spreadThreads), only
// the first tracing it: the traces are those of one invocation a line bit for bit, with history
// and endpoints only, in rounds (the spread widening as lines end).
TEST_P(GpuTracerTest, SpreadLinesTraceAsOneInvocationEach) {
  const flow::VectorVolume volume = volumeOf(rotationAboutZ(0.04, 0.0));
  const flow::SeedList seeds = seedsIn(volume, 48);  // 96 lines
  KernelSettings most = settings_;
  most.spreadThreads = 0x7fffffffu;  // bounded by the device's dispatch size
  const GpuTracer bounded(ctx(), GetParam(), volume, most);
  EXPECT_LE(std::uint64_t(*bounded.settings().spreadThreads),
            std::uint64_t(ctx().limits().maxComputeWorkGroupCount[0]) * 64u);
  for (const bool history : {true, false}) {
    SCOPED_TRACE(history ? "history" : "endpoints");
    flow::TraceOptions options;
    options.maxSteps = 400;
    options.keepHistory = history;
    options.roundSteps = 60;
    std::map<std::uint32_t, flow::TraceSet> traces;
    for (const std::uint32_t threads : {0u, 256u, 4096u}) {
      KernelSettings settings = settings_;
      settings.spreadThreads = threads;
      GpuTracer tracer(ctx(), GetParam(), volume, settings);
      traces[threads] = tracer.trace(seeds.points, options);
      EXPECT_GT(tracer.lastRun().rounds, 3u);
      // 256: 2 a line in the first round of 96 lines, more as lines end.
      const std::uint32_t lanes = tracer.lastRun().mostLanesPerLine;
      EXPECT_EQ(lanes == 1, threads == 0) << lanes;
      EXPECT_EQ(lanes == 32, threads == 4096) << lanes;
    }
    for (const std::uint32_t threads : {256u, 4096u}) {
      SCOPED_TRACE(threads);
      expectSameTraces(traces[threads], traces[0]);
    }
    if (history)
      expectGpuMatchesCpu(traces[4096], flow::traceStreamlines(volume, seeds.points, options),
                          volume);
  }
}

// TraceOptions::cpuTailLines: once a round leaves that many lines or fewer, the CPU reference
// finishes them from the GPU's states; the traces are the CPU's within the GPU's tolerance,
// with history (rounds of the memory budget) and endpoints only (rounds of an eighth of the
// steps, at least 1000).
TEST_P(GpuTracerTest, LinesFinishedOnTheCpuMatchCpu) {
  // Lines leave through the top and bottom at varied steps.
  const flow::VectorVolume volume = volumeOf(rotationAboutZ(0.0, 0.001));
  const flow::SeedList seeds = seedsIn(volume, 40);
  for (const bool history : {true, false}) {
    SCOPED_TRACE(history ? "history" : "endpoints");
    flow::TraceOptions options;
    options.stepMode = flow::StepMode::Arc;
    options.stepSize = 0.5f;
    options.maxSteps = 2400;
    options.keepHistory = history;
    options.memoryBudget = history ? 1 << 20 : 0;
    options.cpuTailLines = 12;
    GpuTracer tracer(ctx(), GetParam(), volume, settings_);
    const flow::TraceSet gpu = tracer.trace(seeds.points, options);
    const TraceRunStats& run = tracer.lastRun();
    EXPECT_GT(run.tailLines, 0u);
    EXPECT_LE(run.tailLines, 12u);
    EXPECT_GT(run.tailSteps, 0u);
    if (!history) {
      EXPECT_EQ(run.rounds, 1u);  // rounds of 1000 steps: the tail after the first
    }
    const flow::TraceSet cpu = flow::traceStreamlines(volume, seeds.points, options);
    if (history)
      expectGpuMatchesCpu(gpu, cpu, volume);
    else
      expectEndpointsMatchCpu(gpu, cpu, volume);
  }
}

// The run statistics the benchmark reports: kernel time from timestamps (positive and within
// the wall time of the run), batches and rounds, and the round buffers' device bytes.
TEST_P(GpuTracerTest, ReportsKernelTimeBatchesRoundsAndDeviceBytes) {
  const bricks::AmrField field = synth::generate("rotation", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = volumeOf(field);
  GpuTracer tracer(ctx(), GetParam(), volume);
  const TracerSetup& setup = tracer.setup();
  EXPECT_EQ(setup.volumeBytes, volume.bricks.size() * sizeof(shared::Brick) +
                                   volume.values.size() * sizeof(glm::vec4) +
                                   volume.regions.regions.size() * sizeof(shared::Region) +
                                   volume.regions.regionBricks.size() * sizeof(shared::Brick));
  if (GetParam() == Backend::Compute)
    EXPECT_EQ(setup.structureBytes, bricks::buildDescentTree(volume.regions).bytes().size());
  else
    EXPECT_GT(setup.structureBytes, volume.regions.regions.size() * sizeof(VkAabbPositionsKHR) / 2);

  flow::TraceOptions options;
  options.maxSteps = 200;
  options.roundSteps = 50;
  options.direction = flow::Direction::Forward;
  const flow::SeedList seeds = seedsIn(volume, 40);
  tracer.limitLinesPerBatch(16);
  tracer.timeKernels(true);
  const auto start = std::chrono::steady_clock::now();
  tracer.trace(seeds.points, options);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const TraceRunStats& run = tracer.lastRun();
  EXPECT_EQ(run.batches, 3u);
  EXPECT_GE(run.rounds, 3u * 1u);
  EXPECT_LE(run.rounds, 3u * 4u);  // 200 steps in rounds of 50
  EXPECT_GT(run.roundBytes, 16u * 51u * sizeof(glm::vec3));
  ASSERT_TRUE(run.kernelSeconds.has_value()) << "lavapipe and NVIDIA have compute timestamps";
  ASSERT_TRUE(run.compactionSeconds.has_value());
  EXPECT_GT(*run.kernelSeconds, 0.0);
  EXPECT_LT(*run.kernelSeconds + *run.compactionSeconds, wall);
}

INSTANTIATE_TEST_SUITE_P(Backends, GpuTracerTest,
                         ::testing::Values(Backend::RayQuery, Backend::Pipeline, Backend::Compute),
                         [](const auto& info) { return std::string(backendName(info.param)); });

}  // namespace
}  // namespace amrstream::gpu
