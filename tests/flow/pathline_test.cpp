// Pathlines and streaklines through snapshot series, against closed forms: the unsteady swirl
// (synth/swirl_field.hpp), whose refinement follows a feature the flow carries so levels change
// between snapshots; second-order convergence as the snapshot interval halves; identical
// snapshots against the streamline tracer in time mode; streaklines of a steady rotation; the
// termination reasons; point data along the paths.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "amrstream/error.hpp"
#include "flow/cpu_tracer.hpp"
#include "flow/pathline_tracer.hpp"
#include "flow/sampler.hpp"
#include "synth/generators.hpp"
#include "synth/swirl_field.hpp"

namespace amrstream::flow {
namespace {

using synth::SwirlField;

const VectorChannels kVelocity{{"velx", "vely", "velz"}, "vel"};

VolumeOptions options(Interpolant interpolant, std::vector<std::string> pointData = {}) {
  VolumeOptions o;
  o.interpolant = interpolant;
  o.pointData = std::move(pointData);
  return o;
}

bricks::AmrField swirlAt(double t) {
  BuiltinOptions g;
  g.levels = 4;
  g.rootBlocks = 2;
  g.targetCells = 60000;
  g.time = t;
  return synth::generate("swirl", g);
}

// The swirl at times 0, interval, 2 interval, ... up to `end`.
struct Series {
  std::vector<double> times;
  std::vector<VectorVolume> volumes;
};

Series swirlSeries(double interval, double end, Interpolant interpolant,
                   std::vector<std::string> pointData = {}) {
  Series series;
  const int count = int(std::lround(end / interval)) + 1;
  for (int i = 0; i < count; ++i) {
    series.times.push_back(i * interval);
    series.volumes.push_back(
        buildVectorVolume(swirlAt(i * interval), kVelocity, options(interpolant, pointData)));
  }
  return series;
}

PathlineTracer traceSeries(const Series& series, std::span<const glm::dvec3> seeds,
                           const PathlineOptions& o, std::vector<std::string> channels = {}) {
  PathlineTracer tracer(seeds, o, "vel", std::move(channels));
  for (std::size_t i = 0; i + 1 < series.times.size(); ++i) {
    if (series.times[i + 1] <= o.startTime) continue;
    if (series.times[i] >= o.endTime) break;
    tracer.advance({series.times[i], &series.volumes[i]},
                   {series.times[i + 1], &series.volumes[i + 1]});
  }
  tracer.finish();
  return tracer;
}

std::vector<glm::dvec3> seedsAroundTheAxis(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> radius(0.08, 0.36), angle(0.0, 2 * std::numbers::pi),
      height(0.3, 0.7);
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < count; ++i) {
    const double r = radius(rng), a = angle(rng);
    seeds.push_back({0.5 + r * std::cos(a), 0.5 + r * std::sin(a), height(rng)});
  }
  return seeds;
}

// The largest distance of a pathline's points from the closed form.
double largestPathError(const TraceSet& set, std::span<const glm::dvec3> seeds, double t0) {
  double worst = 0.0;
  for (std::size_t line = 0; line < set.lineCount(); ++line)
    for (std::uint64_t i = set.offsets[line]; i < set.offsets[line + 1]; ++i) {
      const glm::dvec3 exact = SwirlField::pathline(seeds[set.seedIds[line]], t0, set.times[i]);
      worst = std::max(worst, glm::length(glm::dvec3(set.positions[i]) - exact));
    }
  return worst;
}

TEST(Pathlines, TheSwirlsRefinementMovesBetweenSnapshots) {
  const VectorVolume early = buildVectorVolume(swirlAt(0.0), kVelocity);
  const VectorVolume late = buildVectorVolume(swirlAt(0.25), kVelocity);
  // The feature's place at t = 0 is finest then and coarser a quarter turn on.
  const auto widthAt = [](const VectorVolume& v, glm::dvec3 p) {
    return sampleVector(v, glm::vec3(v.transform.toCellUnits(p))).cellWidth;
  };
  const glm::dvec3 start = SwirlField::kFeatureStart;
  EXPECT_EQ(widthAt(early, start), 1.0f);
  EXPECT_GT(widthAt(late, start), 1.0f);
  EXPECT_EQ(widthAt(late, SwirlField::pathline(start, 0.0, 0.25)), 1.0f);
}

TEST(Pathlines, MatchTheClosedFormAndConvergeAtSecondOrderInTheSnapshotInterval) {
  const std::vector<glm::dvec3> seeds = seedsAroundTheAxis(60, 3);
  std::vector<double> errors;
  for (const double interval : {0.1, 0.05, 0.025}) {
    const Series series = swirlSeries(interval, 0.4, Interpolant::Linear);
    PathlineOptions o;
    o.startTime = 0.0;
    o.stepSize = interval / 8;  // RK4's own error stays far below the time interpolation's
    const PathlineTracer tracer = traceSeries(series, seeds, o);
    const TraceSet set = tracer.pathlines();
    ASSERT_EQ(set.lineCount(), seeds.size());
    for (std::size_t line = 0; line < set.lineCount(); ++line) {
      EXPECT_EQ(set.reasons[line], AMRSTREAM_REASON_SERIES_END);
      EXPECT_FLOAT_EQ(set.times[set.offsets[line + 1] - 1], 0.4f);
    }
    errors.push_back(largestPathError(set, seeds, 0.0));
  }
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    const double order = std::log2(errors[i] / errors[i + 1]);
    std::cout << "interval halved: error " << errors[i] << " -> " << errors[i + 1] << ", order "
              << order << "\n";
    EXPECT_GT(order, 1.8);
    EXPECT_LT(order, 2.2);
  }
  EXPECT_LT(errors.back(), 2e-3);
}

TEST(Pathlines, FollowTheClosedFormWithTheTentToo) {
  const std::vector<glm::dvec3> seeds = seedsAroundTheAxis(30, 5);
  const Series series = swirlSeries(0.025, 0.2, Interpolant::Tent);
  PathlineOptions o;
  o.stepSize = 0.025 / 4;
  const TraceSet set = traceSeries(series, seeds, o).pathlines();
  // The tent errs where levels meet (the linear field's slope times part of a coarse cell):
  // bounded by a few finest cells (1/128 here).
  EXPECT_LT(largestPathError(set, seeds, 0.0), 4.0 / 128);
}

TEST(Pathlines, ThroughIdenticalSnapshotsEqualTimeModeStreamlines) {
  BuiltinOptions g;
  g.levels = 3;
  g.rootBlocks = 2;
  g.targetCells = 30000;
  const VectorVolume volume = buildVectorVolume(synth::generate("rotation", g), kVelocity);
  Series series;
  for (int i = 0; i < 5; ++i) {
    series.times.push_back(0.1 * i);
    series.volumes.push_back(volume);
  }
  const std::vector<glm::dvec3> seeds = seedsAroundTheAxis(40, 9);
  PathlineOptions o;
  o.stepSize = 0.0125;
  const TraceSet paths = traceSeries(series, seeds, o).pathlines();

  TraceOptions t;
  t.stepMode = StepMode::Time;
  t.stepSize = 0.0125f;
  t.maxSteps = 32;
  t.direction = Direction::Forward;
  const TraceSet lines = traceStreamlines(volume, seeds, t);
  ASSERT_EQ(paths.lineCount(), lines.lineCount());
  for (std::size_t line = 0; line < lines.lineCount(); ++line) {
    ASSERT_EQ(paths.pointCount(line), lines.pointCount(line)) << "line " << line;
    for (std::uint64_t k = 0; k < lines.pointCount(line); ++k) {
      const std::uint64_t i = paths.offsets[line] + k, j = lines.offsets[line] + k;
      EXPECT_LT(glm::length(paths.positions[i] - lines.positions[j]), 2e-5f);
      EXPECT_NEAR(paths.times[i], lines.times[j], 1e-5f);
    }
  }
}

TEST(Pathlines, StreaklinesOfASteadyRotationLieOnCircles) {
  BuiltinOptions g;
  g.levels = 3;
  g.rootBlocks = 2;
  g.targetCells = 30000;
  const VectorVolume volume =
      buildVectorVolume(synth::generate("rotation", g), kVelocity, options(Interpolant::Linear));
  Series series;
  for (int i = 0; i < 3; ++i) {
    series.times.push_back(0.2 * i);
    series.volumes.push_back(volume);
  }
  const std::vector<glm::dvec3> seeds{{0.7, 0.5, 0.5}, {0.5, 0.35, 0.6}};
  PathlineOptions o;
  o.stepSize = 0.005;
  o.releaseEvery = 0.05;
  o.endTime = 0.4;
  const PathlineTracer tracer = traceSeries(series, seeds, o);
  const TraceSet streaks = tracer.streaklines();
  ASSERT_EQ(streaks.lineCount(), 2u);
  for (std::size_t line = 0; line < 2; ++line) {
    ASSERT_EQ(streaks.pointCount(line), 8u);  // releases at 0, 0.05, ..., 0.35
    for (std::uint64_t k = 0; k < 8; ++k) {
      const std::uint64_t i = streaks.offsets[line] + k;
      const double age = 0.05 * double(k + 1);  // newest (released at 0.35) first
      EXPECT_NEAR(streaks.times[i], age, 1e-6);
      const glm::dvec3 seed = seeds[streaks.seedIds[line]];
      const double angle = 2 * std::numbers::pi * age;
      const glm::dvec3 r = seed - glm::dvec3(0.5, 0.5, seed.z);
      const glm::dvec3 exact(0.5 + std::cos(angle) * r.x - std::sin(angle) * r.y,
                             0.5 + std::sin(angle) * r.x + std::cos(angle) * r.y, seed.z);
      EXPECT_LT(glm::length(glm::dvec3(streaks.positions[i]) - exact), 1e-4) << "point " << k;
    }
  }
  EXPECT_EQ(tracer.pathlines().lineCount(), 16u);
}

TEST(Pathlines, StopWithTheirReasons) {
  const Series series = swirlSeries(0.1, 0.3, Interpolant::Tent);
  // A seed whose drift carries it out through the top, one that runs to the end time, and one
  // released outside the domain.
  const std::vector<glm::dvec3> seeds{{0.6, 0.5, 0.999}, {0.6, 0.5, 0.5}, {1.5, 0.5, 0.5}};
  PathlineOptions o;
  o.stepSize = 0.01;
  o.endTime = 0.25;
  const TraceSet set = traceSeries(series, seeds, o).pathlines();
  ASSERT_EQ(set.lineCount(), 3u);
  EXPECT_EQ(set.reasons[0], AMRSTREAM_REASON_OUT_OF_DOMAIN);
  EXPECT_EQ(set.reasons[1], AMRSTREAM_REASON_MAX_TIME);
  EXPECT_FLOAT_EQ(set.times[set.offsets[2] - 1], 0.25f);
  EXPECT_EQ(set.reasons[2], AMRSTREAM_REASON_OUT_OF_DOMAIN);
  EXPECT_EQ(set.pointCount(2), 1u);

  o.endTime = std::numeric_limits<double>::infinity();
  o.startTime = 0.15;  // released between two snapshots
  const TraceSet late = traceSeries(series, seeds, o).pathlines();
  EXPECT_EQ(late.reasons[1], AMRSTREAM_REASON_SERIES_END);
  EXPECT_FLOAT_EQ(late.times[late.offsets[1]], 0.15f);
  EXPECT_FLOAT_EQ(late.times[late.offsets[2] - 1], 0.3f);
}

TEST(Pathlines, CarryPointDataInterpolatedInTime) {
  const Series series = swirlSeries(0.05, 0.2, Interpolant::Linear, {"temp"});
  const std::vector<glm::dvec3> seeds = seedsAroundTheAxis(20, 11);
  PathlineOptions o;
  o.stepSize = 0.01;
  const TraceSet set = traceSeries(series, seeds, o, {"temp"}).pathlines();
  ASSERT_EQ(set.channelNames, std::vector<std::string>{"temp"});
  double worst = 0.0;
  for (std::uint64_t i = 0; i < set.pointCount(); ++i)
    worst = std::max(worst,
                     std::abs(set.channels[i] -
                              SwirlField::temperature(glm::dvec3(set.positions[i]), set.times[i])));
  // temp is linear in space and in time: exact but for float rounding.
  EXPECT_LT(worst, 1e-5);
}

// The viewer's frames: each interval in advances of a few steps (a stop inside the interval)
// makes the lines of whole intervals, bit for bit, whether the storage was planned for the series
// or grows with each advance; what each advance added (lastGrowth), each piece after its line's
// last point from before, adds up to the lines.
TEST(Pathlines, AFewStepsAtATimeMakeTheLinesOfWholeIntervals) {
  const Series series = swirlSeries(0.05, 0.2, Interpolant::Tent, {"temp"});
  std::vector<glm::dvec3> seeds = seedsAroundTheAxis(30, 13);
  seeds.push_back({0.6, 0.5, 0.999});  // leaves through the top
  for (const auto& [streaks, planned] : {std::pair{false, false}, std::pair{false, true},
                                         std::pair{true, false}, std::pair{true, true}}) {
    SCOPED_TRACE(std::string(streaks ? "streaklines" : "pathlines") +
                 (planned ? ", storage planned" : ""));
    PathlineOptions o;
    o.stepSize = 0.01;
    o.endTime = 0.17;                     // within the last interval
    if (streaks) o.releaseEvery = 0.015;  // releases between the frames' stops
    o.maxResultBytes = std::uint64_t(1) << 30;
    const PathlineTracer whole = traceSeries(series, seeds, o, {"temp"});
    PathlineTracer frames(seeds, o, "vel", {"temp"});
    if (planned) frames.planStorage(series.times);
    std::vector<std::vector<glm::vec3>> grown(seeds.size());  // pathlines: a seed is a line
    std::size_t advances = 0;
    for (std::size_t i = 0; i + 1 < series.times.size() && series.times[i] < o.endTime; ++i) {
      const Snapshot a{series.times[i], &series.volumes[i]};
      const Snapshot b{series.times[i + 1], &series.volumes[i + 1]};
      for (double t = a.time; t < std::min(b.time, o.endTime);) {
        const double stopAt = t + 3 * o.stepSize;
        frames.advance(a, b, nullptr,
                       stopAt >= b.time ? std::numeric_limits<double>::infinity() : stopAt);
        ++advances;
        const TraceSet piece = frames.lastGrowth();
        // The stop holds: the advance took the steps that end by it, and no more.
        EXPECT_GT(piece.pointCount(), 0u);
        const float reached = *std::max_element(piece.times.begin(), piece.times.end());
        EXPECT_LE(reached, float(std::min({stopAt, b.time, o.endTime})));
        EXPECT_GT(reached + 1e-6f, float(std::min({stopAt, b.time, o.endTime}) - o.stepSize));
        t = stopAt;
        for (std::size_t line = 0; !streaks && line < piece.lineCount(); ++line) {
          std::vector<glm::vec3>& points = grown[piece.seedIds[line]];
          std::uint64_t first = piece.offsets[line];
          if (!points.empty()) {
            EXPECT_EQ(piece.positions[first], points.back()) << "the tail";
            ++first;
          }
          points.insert(points.end(), piece.positions.begin() + std::ptrdiff_t(first),
                        piece.positions.begin() + std::ptrdiff_t(piece.offsets[line + 1]));
        }
      }
    }
    frames.finish();
    EXPECT_EQ(advances, 7u);  // 2 a whole interval, 1 in the last's first 0.02
    for (const bool streaklines : {false, true}) {
      const TraceSet want = streaklines ? whole.streaklines() : whole.pathlines();
      const TraceSet got = streaklines ? frames.streaklines() : frames.pathlines();
      ASSERT_EQ(got.offsets, want.offsets);
      EXPECT_EQ(got.reasons, want.reasons);
      EXPECT_EQ(got.steps, want.steps);
      EXPECT_EQ(got.seedIds, want.seedIds);
      for (std::uint64_t i = 0; i < want.pointCount(); ++i) {
        ASSERT_EQ(got.positions[i], want.positions[i]) << "point " << i;
        ASSERT_EQ(got.times[i], want.times[i]) << "point " << i;
        ASSERT_EQ(got.channels[i], want.channels[i]) << "point " << i;
      }
    }
    if (streaks) continue;
    const TraceSet want = whole.pathlines();
    EXPECT_NE(std::count(want.reasons.begin(), want.reasons.end(), AMRSTREAM_REASON_OUT_OF_DOMAIN),
              0);
    for (std::size_t line = 0; line < want.lineCount(); ++line) {
      const std::vector<glm::vec3> points(
          want.positions.begin() + std::ptrdiff_t(want.offsets[line]),
          want.positions.begin() + std::ptrdiff_t(want.offsets[line + 1]));
      EXPECT_EQ(grown[want.seedIds[line]], points) << "line " << line;
    }
  }
}

// Storage planned for the series holds each particle's points in one run: the lines are the same
// as without the plan, taken in place (takePathlines) or copied; a plan that would pass the
// result's limit is dropped, and the limit still holds.
TEST(Pathlines, StoragePlannedForTheSeriesGivesTheSameLines) {
  const Series series = swirlSeries(0.05, 0.2, Interpolant::Linear, {"temp"});
  std::vector<glm::dvec3> seeds = seedsAroundTheAxis(40, 17);
  seeds.push_back({0.6, 0.5, 0.999});  // leaves through the top: its run is not filled
  seeds.push_back({1.5, 0.5, 0.5});    // outside: one point
  PathlineOptions o;
  o.stepSize = 0.007;
  const TraceSet want = traceSeries(series, seeds, o, {"temp"}).pathlines();
  EXPECT_EQ(want.reasons.back(), AMRSTREAM_REASON_OUT_OF_DOMAIN);
  for (const std::uint64_t limit : {std::uint64_t(1) << 30, std::uint64_t(40000)}) {
    SCOPED_TRACE(limit);
    o.maxResultBytes = limit;
    PathlineTracer planned(seeds, o, "vel", {"temp"});
    planned.planStorage(series.times);
    bool refused = false;
    for (std::size_t i = 0; i + 1 < series.times.size() && !refused; ++i) try {
        planned.advance({series.times[i], &series.volumes[i]},
                        {series.times[i + 1], &series.volumes[i + 1]});
      } catch (const InputError&) {
        refused = true;
      }
    EXPECT_EQ(refused, limit < want.pointCount() * 32);
    if (refused) continue;
    planned.finish();
    const TraceSet copied = planned.pathlines();
    const TraceSet taken = std::move(planned).takePathlines();
    for (const TraceSet* got : {&copied, &taken}) {
      ASSERT_EQ(got->offsets, want.offsets);
      EXPECT_EQ(got->reasons, want.reasons);
      EXPECT_EQ(got->steps, want.steps);
      EXPECT_EQ(got->positions, want.positions);
      EXPECT_EQ(got->times, want.times);
      EXPECT_EQ(got->vectors, want.vectors);
      ASSERT_EQ(got->channels.size(), want.channels.size());
      for (std::size_t i = 0; i < want.channels.size(); ++i)  // NaN where outside
        ASSERT_TRUE(got->channels[i] == want.channels[i] ||
                    (std::isnan(got->channels[i]) && std::isnan(want.channels[i])))
            << "value " << i;
    }
  }
}

TEST(Pathlines, RejectBadOptions) {
  const std::vector<glm::dvec3> seeds{{0.5, 0.5, 0.5}};
  PathlineOptions o;
  EXPECT_THROW(PathlineTracer(seeds, o, "v", {}), std::invalid_argument);  // no step
  o.stepSize = 0.1;
  o.endTime = -1.0;
  EXPECT_THROW(PathlineTracer(seeds, o, "v", {}), std::invalid_argument);
  o.endTime = std::numeric_limits<double>::infinity();
  o.releaseEvery = 0.1;
  EXPECT_THROW(PathlineTracer(seeds, o, "v", {}), std::invalid_argument);
}

}  // namespace
}  // namespace amrstream::flow
