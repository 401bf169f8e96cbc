// amrstream's CPU tracer (positions as a finest cell plus a float offset, rk4 in `time` steps, the
// tent interpolant) against the independent double-precision oracle of tests/support: the same
// reconstruction, the same steps and ends, and positions within kToleranceCells finest cells,
// along traces that cross level boundaries, on shallow data and on two nests 2^30 finest cells
// wide (28 levels properly nested, 30 levels as an octree), where float32 cell units would be 8
// to 32 finest cells apart.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <set>

#include "deep_nest.hpp"
#include "double_tracer.hpp"
#include "flow/cpu_tracer.hpp"
#include "flow/sampler.hpp"
#include "flow_test_support.hpp"
#include "synth/generators.hpp"
#include "synth/nest_generator.hpp"

namespace amrstream::flow {
namespace {

using testing::DoubleTrace;
using testing::DoubleTraceEnd;

// Finest cells. Each step rounds the offset (in [0, 1) cells) by up to 2^-24 cells and its stages
// carry float32 rounding relative to their displacements: over 200 steps well under 1e-3 cells,
// at any depth. Measured before positions had anchors, with float32 cell units: 1.2e-4 on the
// 6-level nest, 7e-5 in the cloud, and 2.2 cells on a 19-level nest.
constexpr double kToleranceCells = 1e-3;

int reasonOf(DoubleTraceEnd end) {
  switch (end) {
    case DoubleTraceEnd::StepsDone:
      return AMRSTREAM_REASON_MAX_STEPS;
    case DoubleTraceEnd::OutOfDomain:
      return AMRSTREAM_REASON_OUT_OF_DOMAIN;
    case DoubleTraceEnd::InvalidSample:
      return AMRSTREAM_REASON_UNEXPECTED_VALUE;
  }
  return -1;
}

struct Agreement {
  double worstCells = 0.0;               // largest position difference, finest cells
  std::vector<std::size_t> levelCounts;  // per seed: levels of the leaf cells along its trace
  std::vector<int> reasons;              // per seed
};

// Traces every seed forward on the CPU and with the oracle, expecting the same steps and ends.
Agreement compareWithDouble(const bricks::AmrField& field, const std::vector<glm::dvec3>& seeds,
                            float h, std::uint32_t steps) {
  const VectorChannels vector = chooseVectorChannels(field, "");
  TraceOptions options;
  options.stepMode = StepMode::Time;
  options.integrator = Integrator::Rk4;
  options.stepSize = h;
  options.maxSteps = steps;
  options.direction = Direction::Forward;
  const TraceSet cpu = traceStreamlines(buildVectorVolume(field, vector), seeds, options);

  const testing::DoubleTracer oracle(field, vector.channels);
  const WorldTransform& transform = field.transform();
  Agreement agreement;
  for (std::size_t line = 0; line < seeds.size(); ++line) {
    SCOPED_TRACE(::testing::Message() << "seed " << line);
    const DoubleTrace exact = oracle.trace(seeds[line], double(h), steps);
    EXPECT_EQ(cpu.steps[line], exact.steps());
    EXPECT_EQ(cpu.reasons[line], reasonOf(exact.end));
    std::set<int> levels;
    const std::size_t points = std::min<std::size_t>(cpu.pointCount(line), exact.positions.size());
    for (std::size_t k = 0; k < points; ++k) {
      const std::size_t at = cpu.firstPoint(line) + k;
      const glm::dvec3 p = transform.toCellUnits(exact.positions[k]);
      const glm::dvec3 q = transform.toCellUnits(
          cpu.precisePositions ? joinPosition(cpu.positions[at], cpu.positionsLow[at])
                               : glm::dvec3(cpu.positions[at]));
      agreement.worstCells = std::max(agreement.worstCells, glm::length(p - q));
      levels.insert(oracle.field().levelAt(p));
    }
    agreement.levelCounts.push_back(levels.size());
    agreement.reasons.push_back(reasonOf(exact.end));
  }
  return agreement;
}

std::size_t seedsCrossingLevels(const Agreement& agreement) {
  return std::size_t(
      std::ranges::count_if(agreement.levelCounts, [](std::size_t n) { return n > 1; }));
}

std::size_t count(const std::vector<int>& reasons, int reason) {
  return std::size_t(std::ranges::count(reasons, reason));
}

TEST(CpuTracerVsDouble, ReconstructionMatchesTheSampler) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    testing::RandomAmrOptions layout;
    layout.levels = 1 + int(seed % 5);
    const bricks::AmrField field = testing::randomAmr(seed, layout);
    const VectorVolume volume = testing::volumeOf(field);
    const testing::TentField oracle(field, {"vx", "vy", "vz"});
    const glm::dvec3 lower(field.bounds().lower), upper(field.bounds().upper);
    for (int k = 0; k < 300; ++k) {
      const glm::vec3 p(lower + glm::dvec3(u(rng), u(rng), u(rng)) * (upper - lower));
      const VectorSample s = sampleVector(volume, p);
      const testing::TentSample exact = oracle.sample(glm::dvec3(p));
      ASSERT_TRUE(s.valid);
      ASSERT_EQ(exact.status, testing::TentSample::Status::Valid);
      EXPECT_LT(glm::length(glm::dvec3(s.value) - exact.value), 1e-5);  // values in [-1, 1]
    }
  }
}

// Seeds about the centre of a six-level nest: at 5 finest cells in and out of the finest cube at
// its corners, then out across the levels as the spiral widens; the last one leaves the domain.
TEST(CpuTracerVsDouble, AgreeAcrossTheLevelsOfANest) {
  NestOptions nest;
  nest.levels = 6;
  const bricks::AmrField field = synth::generateNest(nest);
  const glm::dvec3 centre = nest.centre / field.transform().spacing;
  std::vector<glm::dvec3> seeds;
  for (const glm::dvec3 offset :
       {glm::dvec3(5.0, 0.0, 0.3), glm::dvec3(0.0, -11.0, 1.0), glm::dvec3(-20.0, 14.0, -3.0),
        glm::dvec3(40.0, 0.0, 2.0), glm::dvec3(75.0, 5.0, 0.0)})
    seeds.push_back(field.transform().toPhysical(centre + offset));
  const Agreement agreement = compareWithDouble(field, seeds, 1.0f / 128, 200);
  std::printf("nest, 6 levels: largest difference %.3g finest cells\n", agreement.worstCells);
  EXPECT_LE(agreement.worstCells, kToleranceCells);
  EXPECT_EQ(seedsCrossingLevels(agreement), seeds.size());
  EXPECT_GE(std::ranges::max(agreement.levelCounts), 3u);
  EXPECT_GE(count(agreement.reasons, AMRSTREAM_REASON_MAX_STEPS), 1u);
  EXPECT_GE(count(agreement.reasons, AMRSTREAM_REASON_OUT_OF_DOMAIN), 1u);
}

// A deep nest of tests/support, 2^30 finest cells per axis, traced 400 steps from its seeds:
// within the tolerance of the oracle, every seed's trace crossing levels.
void expectDeepNestAgrees(const testing::DeepNest& nest, const char* name) {
  ASSERT_EQ(nest.field.bounds().upper.x - nest.field.bounds().lower.x, 1 << 30);
  const Agreement agreement = compareWithDouble(nest.field, nest.seeds, 1.0f / 128, 400);
  std::printf("%s, 2^30 cells wide: largest difference %.3g finest cells\n", name,
              agreement.worstCells);
  EXPECT_LE(agreement.worstCells, kToleranceCells);
  EXPECT_EQ(seedsCrossingLevels(agreement), nest.seeds.size());
  EXPECT_GE(std::ranges::max(agreement.levelCounts), 3u);
}

// 28 levels properly nested, where float32 cell units would be 16 to 32 finest cells apart.
TEST(CpuTracerVsDouble, AgreeAcrossTheLevelsOfANestTwoToTheThirtyCellsWide) {
  expectDeepNestAgrees(testing::deepNest(), "nest, 28 levels");
}

// The 30-level octree, where float32 cell units would be 8 to 16 finest cells apart.
TEST(CpuTracerVsDouble, AgreeAcrossTheThirtyLevelsOfAnOctreeNest) {
  const testing::DeepNest nest = testing::deepOctreeNest();
  ASSERT_EQ(nest.field.cellsPerLevel().size(), 30u);
  expectDeepNestAgrees(nest, "octree nest, 30 levels");
}

// The cloud's refinement follows its filaments: field lines from its finest cells run out through
// coarser blocks, most of them out of the domain. Steps move at most one finest cell.
TEST(CpuTracerVsDouble, AgreeInTheCloud) {
  BuiltinOptions g;
  g.levels = 4;
  g.rootBlocks = 2;
  g.targetCells = 40'000;
  const bricks::AmrField field = synth::generate("cloud", g);
  const std::vector<float>& bx = field.channel("magx").values;
  const std::vector<float>& by = field.channel("magy").values;
  const std::vector<float>& bz = field.channel("magz").values;
  const int finestLevel = field.finestLevel();
  double fastest = 0.0;
  std::vector<std::size_t> finest;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    fastest = std::max(fastest, glm::length(glm::dvec3(bx[i], by[i], bz[i])));
    if (field.levels()[i] == finestLevel) finest.push_back(i);
  }
  const float h = float(field.transform().spacing.x / fastest);
  std::vector<glm::dvec3> seeds;
  for (std::size_t k = 0; k < 12; ++k) {
    const std::size_t cell = finest[k * finest.size() / 12];
    seeds.push_back(field.transform().toPhysical(glm::dvec3(field.lowers()[cell]) + 0.3));
  }
  const Agreement agreement = compareWithDouble(field, seeds, h, 200);
  std::printf("cloud, 4 levels: largest difference %.3g finest cells\n", agreement.worstCells);
  EXPECT_LE(agreement.worstCells, kToleranceCells);
  EXPECT_GE(seedsCrossingLevels(agreement), seeds.size() * 2 / 3);
  EXPECT_GE(count(agreement.reasons, AMRSTREAM_REASON_MAX_STEPS), 1u);
  EXPECT_GE(count(agreement.reasons, AMRSTREAM_REASON_OUT_OF_DOMAIN), 1u);
}

}  // namespace
}  // namespace amrstream::flow
