// Pathlines with every GPU backend's samples (gpu::VectorProbe) against the CPU reference: the
// probe's samples equal flow::sampleVector at random points and region faces; pathlines and
// streaklines through a swirl series whose refinement moves, with the host stepping on the
// probe's samples or the device stepping (gpu::PathlineStepper), have the CPU's lines, steps and
// reasons, and positions within float rounding, with either interpolant; advanced a few steps at a
// time (the viewer's frames), the device's lines are those of whole intervals.

#include <gtest/gtest.h>

#include <random>

#include "flow/pathline_tracer.hpp"
#include "flow/sampler.hpp"
#include "gpu/pathline_stepper.hpp"
#include "gpu/vector_probe.hpp"
#include "gpu_test.hpp"
#include "synth/generators.hpp"

namespace amrstream::gpu {
namespace {

const flow::VectorChannels kVelocity{{"velx", "vely", "velz"}, "vel"};

flow::VectorVolume swirlVolume(double t, flow::Interpolant interpolant) {
  BuiltinOptions g;
  g.levels = 3;
  g.rootBlocks = 2;
  g.targetCells = 12000;
  g.time = t;
  flow::VolumeOptions options;
  options.interpolant = interpolant;
  options.pointData = {"temp"};
  return flow::buildVectorVolume(synth::generate("swirl", g), kVelocity, options);
}

class GpuPathlineTest : public testing::GpuTest, public ::testing::WithParamInterface<Backend> {
 protected:
  vk::CapabilitySet required() const override { return requiredCapabilities(GetParam()); }
};

TEST_P(GpuPathlineTest, ProbeSamplesEqualTheCpusSampler) {
  const flow::VectorVolume volume = swirlVolume(0.1, flow::Interpolant::Linear);
  const TraceKernel kernel = createTraceKernel(ctx(), GetParam(), KernelProgram::LocateProbe);
  VectorProbe probe(ctx(), kernel, volume);
  std::vector<glm::vec3> points;
  std::mt19937_64 rng(5);
  const glm::vec3 lower(volume.domain.lower), upper(volume.domain.upper);
  std::uniform_real_distribution<float> u(-0.05f, 1.05f);
  for (int i = 0; i < 3000; ++i)
    points.push_back(lower + glm::vec3(u(rng), u(rng), u(rng)) * (upper - lower));
  for (const shared::Region& r : volume.regions.regions) points.push_back(r.lower);
  std::vector<flow::VectorSample> samples(points.size());
  probe.sample(points, samples);
  std::size_t located = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const flow::VectorSample expected = flow::sampleVector(volume, points[i]);
    ASSERT_EQ(samples[i].located, expected.located) << "point " << i;
    ASSERT_EQ(samples[i].valid, expected.valid) << "point " << i;
    if (!expected.located) continue;
    ++located;
    EXPECT_EQ(samples[i].region, expected.region);
    EXPECT_EQ(samples[i].cellWidth, expected.cellWidth);
    EXPECT_LT(glm::length(samples[i].value - expected.value), 1e-5f) << "point " << i;
  }
  EXPECT_GT(located, points.size() / 2);
}

TEST_P(GpuPathlineTest, PathlinesAndStreaklinesEqualTheCpus) {
  for (const flow::Interpolant interpolant : {flow::Interpolant::Tent, flow::Interpolant::Linear}) {
    std::vector<double> times;
    std::vector<flow::VectorVolume> volumes;
    for (int i = 0; i < 4; ++i) {
      times.push_back(0.05 * i);
      volumes.push_back(swirlVolume(0.05 * i, interpolant));
    }
    const TraceKernel kernel = createTraceKernel(ctx(), GetParam(), KernelProgram::LocateProbe);
    std::vector<std::unique_ptr<VectorProbe>> probes;
    for (const flow::VectorVolume& v : volumes)
      probes.push_back(std::make_unique<VectorProbe>(ctx(), kernel, v));

    // Rounds of one step and moves of 40 particles (compute), or of the whole interval.
    const bool small = GetParam() == Backend::Compute;
    PathlineStepper stepper(ctx(), kernel, small ? 2048 : 1 << 20, small ? 40 : 1 << 22);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    std::vector<glm::dvec3> seeds;
    for (int i = 0; i < 48; ++i) seeds.push_back({u(rng), u(rng), u(rng)});  // some leave
    flow::PathlineOptions options;
    options.stepSize = 0.01;
    options.releaseEvery = 0.04;
    options.endTime = 0.15;
    flow::PathlineTracer cpu(seeds, options, "vel", {"temp"}), gpu(seeds, options, "vel", {"temp"}),
        device(seeds, options, "vel", {"temp"}), frames(seeds, options, "vel", {"temp"});
    for (std::size_t i = 0; i + 1 < times.size(); ++i) {
      cpu.advance({times[i], &volumes[i], {}}, {times[i + 1], &volumes[i + 1], {}});
      VectorProbe* a = probes[i].get();
      VectorProbe* b = probes[i + 1].get();
      const flow::Snapshot probedA{times[i], &volumes[i],
                                   [a](auto cells, auto out) { a->sample(cells, out); }};
      const flow::Snapshot probedB{times[i + 1], &volumes[i + 1],
                                   [b](auto cells, auto out) { b->sample(cells, out); }};
      gpu.advance(probedA, probedB);
      stepper.bind(*a, *b);
      device.advance(probedA, probedB, &stepper);
      // The viewer's frames: two steps at a time.
      for (double t = times[i]; t < std::min(times[i + 1], options.endTime); t += 0.02)
        frames.advance(
            probedA, probedB, &stepper,
            t + 0.02 >= times[i + 1] ? std::numeric_limits<double>::infinity() : t + 0.02);
    }
    EXPECT_GT(stepper.times().rounds, 0u);
    // Advanced a few steps at a time, the device makes the lines of whole intervals exactly.
    const flow::TraceSet whole = device.pathlines(), framed = frames.pathlines();
    ASSERT_EQ(framed.offsets, whole.offsets);
    EXPECT_EQ(framed.reasons, whole.reasons);
    EXPECT_EQ(framed.positions, whole.positions);
    EXPECT_EQ(framed.channels, whole.channels);
    for (const auto& [tracer, what] : {std::pair{&gpu, "samples"}, std::pair{&device, "steps"}})
      for (const bool streaks : {false, true}) {
        SCOPED_TRACE(std::string(what) + (streaks ? ", streaklines" : ", pathlines"));
        const flow::TraceSet want = streaks ? cpu.streaklines() : cpu.pathlines();
        const flow::TraceSet got = streaks ? tracer->streaklines() : tracer->pathlines();
        ASSERT_EQ(got.lineCount(), want.lineCount());
        EXPECT_EQ(got.reasons, want.reasons);
        EXPECT_EQ(got.steps, want.steps);
        ASSERT_EQ(got.offsets, want.offsets);
        float worst = 0.0f, worstVector = 0.0f, worstChannel = 0.0f;
        for (std::uint64_t i = 0; i < want.pointCount(); ++i) {
          worst = std::max(worst, glm::length(got.positions[i] - want.positions[i]));
          worstVector = std::max(worstVector, glm::length(got.vectors[i] - want.vectors[i]));
          EXPECT_FLOAT_EQ(got.times[i], want.times[i]);
          worstChannel = std::max(worstChannel, std::abs(got.channels[i] - want.channels[i]));
        }
        EXPECT_LT(worst, 1e-5f);
        EXPECT_LT(worstVector, 1e-4f);
        EXPECT_LT(worstChannel, 1e-5f);
      }
    const flow::TraceSet paths = cpu.pathlines();
    EXPECT_GT(paths.lineCount(), 48u * 3);
    EXPECT_NE(
        std::count(paths.reasons.begin(), paths.reasons.end(), AMRSTREAM_REASON_OUT_OF_DOMAIN), 0);
    EXPECT_NE(std::count(paths.reasons.begin(), paths.reasons.end(), AMRSTREAM_REASON_MAX_TIME), 0);
  }
}

// Through a steady periodic field (ABC) whose particles cross the domain's faces: positions wrap
// into snapshot A's domain, on the device as on the CPU.
TEST_P(GpuPathlineTest, PeriodicPathlinesOnTheDeviceEqualTheCpus) {
  std::vector<flow::VectorVolume> volumes;
  for (int i = 0; i < 3; ++i) {
    BuiltinOptions g;
    g.levels = 2;
    g.rootBlocks = 2;
    g.targetCells = 6000;
    flow::VolumeOptions options;
    options.periodic = {true, true, true};
    volumes.push_back(flow::buildVectorVolume(synth::generate("abc", g), kVelocity, options));
  }
  const TraceKernel kernel = createTraceKernel(ctx(), GetParam(), KernelProgram::LocateProbe);
  std::vector<std::unique_ptr<VectorProbe>> probes;
  for (const flow::VectorVolume& v : volumes)
    probes.push_back(std::make_unique<VectorProbe>(ctx(), kernel, v));
  PathlineStepper stepper(ctx(), kernel);
  const glm::dvec3 lower = volumes[0].transform.toPhysical(glm::dvec3(volumes[0].domain.lower));
  const glm::dvec3 upper = volumes[0].transform.toPhysical(glm::dvec3(volumes[0].domain.upper));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < 32; ++i)
    seeds.push_back(lower + glm::dvec3(u(rng), u(rng), u(rng)) * (upper - lower));
  flow::PathlineOptions options;
  options.stepSize = 0.05;
  options.endTime = 2.0;
  flow::PathlineTracer cpu(seeds, options, "vel", {}), device(seeds, options, "vel", {});
  for (std::size_t i = 0; i + 1 < volumes.size(); ++i) {
    const flow::Snapshot a{double(i), &volumes[i], {}}, b{double(i + 1), &volumes[i + 1], {}};
    cpu.advance(a, b);
    VectorProbe* pa = probes[i].get();
    VectorProbe* pb = probes[i + 1].get();
    stepper.bind(*pa, *pb);
    device.advance({a.time, a.volume, [pa](auto cells, auto out) { pa->sample(cells, out); }},
                   {b.time, b.volume, [pb](auto cells, auto out) { pb->sample(cells, out); }},
                   &stepper);
  }
  const flow::TraceSet want = cpu.pathlines(), got = device.pathlines();
  ASSERT_EQ(got.offsets, want.offsets);
  EXPECT_EQ(got.reasons, want.reasons);
  float worst = 0.0f;
  std::size_t wraps = 0;
  const float halfDomain = float(0.5 * (upper.x - lower.x));
  for (std::size_t line = 0; line < want.lineCount(); ++line)
    for (std::uint64_t i = want.offsets[line]; i < want.offsets[line + 1]; ++i) {
      worst = std::max(worst, glm::length(got.positions[i] - want.positions[i]));
      if (i > want.offsets[line] &&
          glm::any(glm::greaterThan(glm::abs(want.positions[i] - want.positions[i - 1]),
                                    glm::vec3(halfDomain))))
        ++wraps;
    }
  EXPECT_LT(worst, 1e-4f);  // the domain is 2 pi wide
  EXPECT_GT(wraps, 0u);     // particles crossed faces
}

INSTANTIATE_TEST_SUITE_P(Backends, GpuPathlineTest,
                         ::testing::Values(Backend::RayQuery, Backend::Pipeline, Backend::Compute),
                         [](const auto& info) { return std::string(backendName(info.param)); });

}  // namespace
}  // namespace amrstream::gpu
