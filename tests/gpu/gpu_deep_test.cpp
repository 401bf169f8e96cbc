// Deep hierarchies on the GPU: the nests 2^30 finest cells wide of tests/support (28 levels
// properly nested, 30 levels as an octree), traced by the compute and rayquery backends, against
// the independent double-precision oracle; the pipeline backend, whose intersection shader sees
// only the float ray origin, refuses them.

#include <gtest/gtest.h>

#include <algorithm>

#include "amrstream/error.hpp"
#include "deep_nest.hpp"
#include "double_tracer.hpp"
#include "flow/trace_options.hpp"
#include "flow/vector_selection.hpp"
#include "gpu/gpu_tracer.hpp"
#include "gpu_test.hpp"

namespace amrstream::gpu {
namespace {

// Finest cells: the CPU agrees with the oracle to 5e-6 cells over these 400 steps; the GPU's
// division and square root may round a few ulp more (gpu_tracer_test.cpp), far below this, and
// float32 cell units there would be 16 cells apart.
constexpr double kToleranceCells = 1e-3;

class GpuDeepTest : public testing::GpuTest, public ::testing::WithParamInterface<Backend> {
 protected:
  vk::CapabilitySet required() const override { return requiredCapabilities(GetParam()); }
};

flow::TraceOptions nestOptions() {
  flow::TraceOptions options;
  options.stepMode = flow::StepMode::Time;
  options.integrator = flow::Integrator::Rk4;
  options.stepSize = 1.0f / 128;
  options.maxSteps = 400;
  options.direction = flow::Direction::Forward;
  return options;
}

// The largest position difference from the oracle, in finest cells; a negative value if the
// backend refused the volume.
double worstDifference(vk::Context& ctx, Backend backend, const testing::DeepNest& nest) {
  const bricks::AmrField& field = nest.field;
  const std::vector<glm::dvec3>& seeds = nest.seeds;
  const flow::VectorChannels vector = flow::chooseVectorChannels(field, "");
  const flow::VectorVolume volume = flow::buildVectorVolume(field, vector);
  EXPECT_TRUE(volume.deepPositions());
  const flow::TraceOptions options = nestOptions();
  if (backend == Backend::Pipeline) {
    EXPECT_THROW(GpuTracer(ctx, backend, volume), InputError);
    return -1.0;
  }
  GpuTracer tracer(ctx, backend, volume);
  tracer.setStaging(2, 1000);  // the points and their region ids come back a few dozen at a time
  const flow::TraceSet gpu = tracer.trace(seeds, options);
  EXPECT_TRUE(gpu.precisePositions);
  if (!gpu.precisePositions) return -1.0;

  const testing::DoubleTracer oracle(field, vector.channels);
  const WorldTransform& transform = field.transform();
  double worst = 0.0;
  for (std::size_t line = 0; line < seeds.size(); ++line) {
    const testing::DoubleTrace exact = oracle.trace(seeds[line], double(options.stepSize), 400);
    EXPECT_EQ(gpu.steps[line], exact.steps()) << "line " << line;
    EXPECT_EQ(gpu.pointCount(line), exact.positions.size()) << "line " << line;
    if (gpu.pointCount(line) != exact.positions.size()) continue;
    for (std::size_t k = 0; k < exact.positions.size(); ++k) {
      const std::size_t at = gpu.firstPoint(line) + k;
      const glm::dvec3 traced = flow::joinPosition(gpu.positions[at], gpu.positionsLow[at]);
      worst = std::max(worst, glm::length(transform.toCellUnits(traced) -
                                          transform.toCellUnits(exact.positions[k])));
    }
  }
  return worst;
}

TEST_P(GpuDeepTest, TracesANestTwoToTheThirtyCellsWideAsTheDoubleOracle) {
  const double worst = worstDifference(ctx(), GetParam(), testing::deepNest());
  if (GetParam() == Backend::Pipeline) return;
  std::printf("%s, 28 levels: largest difference from the oracle %.3g finest cells\n",
              std::string(backendName(GetParam())).c_str(), worst);
  EXPECT_GE(worst, 0.0);
  EXPECT_LE(worst, kToleranceCells);
}

TEST_P(GpuDeepTest, TracesTheThirtyLevelsOfAnOctreeNestAsTheDoubleOracle) {
  const testing::DeepNest nest = testing::deepOctreeNest();
  ASSERT_EQ(nest.field.cellsPerLevel().size(), 30u);
  const double worst = worstDifference(ctx(), GetParam(), nest);
  if (GetParam() == Backend::Pipeline) return;
  std::printf("%s, 30-level octree: largest difference from the oracle %.3g finest cells\n",
              std::string(backendName(GetParam())).c_str(), worst);
  EXPECT_GE(worst, 0.0);
  EXPECT_LE(worst, kToleranceCells);
}

INSTANTIATE_TEST_SUITE_P(Backends, GpuDeepTest,
                         ::testing::Values(Backend::RayQuery, Backend::Pipeline, Backend::Compute),
                         [](const auto& info) { return std::string(backendName(info.param)); });

}  // namespace
}  // namespace amrstream::gpu
