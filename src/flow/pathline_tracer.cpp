#include "pathline_tracer.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "amrstream/error.hpp"
#include "morton_order.hpp"
#include "sampler.hpp"

namespace amrstream::flow {

namespace {

// A step this much shorter than dt that would be left before an interval's end is taken with
// the step before it: float rounding of the time must not make a sliver of a step.
constexpr double kSliverFraction = 1e-4;

glm::vec3 cellOf(const VectorVolume& volume, glm::vec3 x) {
  return glm::vec3(
      toCellUnits(wrapPeriodic(volume, toCellPoint(volume.transform.toCellUnits(glm::dvec3(x))))));
}

// x moved by whole periods into the volume's domain along its periodic axes.
glm::vec3 wrapPhysical(const VectorVolume& volume, glm::vec3 x) {
  if (!(volume.periodic[0] || volume.periodic[1] || volume.periodic[2])) return x;
  return glm::vec3(volume.transform.toPhysical(glm::dvec3(cellOf(volume, x))));
}

// The step a particle at time t takes toward `until`, and the time the step ends at: dt, or the
// rest of the interval for its last step.
struct TimeStep {
  double h = 0.0, end = 0.0;
  bool last = false;
};

TimeStep timeStep(double t, double until, double stepSize) {
  TimeStep s;
  s.h = std::min(stepSize, until - t);
  s.last = until - (t + s.h) < kSliverFraction * stepSize;
  if (s.last) s.h = until - t;
  s.end = s.last ? until : t + s.h;
  return s;
}

// Whether step s ends by `reach` (to a sliver: float rounding of the times must not hold a step
// back a frame).
bool endsBy(const TimeStep& s, double reach, double stepSize) {
  return s.end <= reach + kSliverFraction * stepSize;
}

// The weight of snapshot b at time t, as sampleAt() takes it.
float weightOfB(const Snapshot& a, const Snapshot& b, double t) {
  return float((t - a.time) / (b.time - a.time));
}

// The steps the particles at time `start` take through the interval, as move() takes them, and
// the time each ends at.
struct GroupSteps {
  std::vector<shared::PathlineStep> steps;
  std::vector<double> ends;
};

GroupSteps planSteps(double start, double until, double reach, const PathlineOptions& options,
                     const Snapshot& a, const Snapshot& b) {
  GroupSteps plan;
  double t = start;
  for (;;) {
    const TimeStep s = timeStep(t, until, options.stepSize);
    if (!plan.steps.empty() && !endsBy(s, reach, options.stepSize)) return plan;
    shared::PathlineStep& step = plan.steps.emplace_back();
    step.h = float(s.h);
    step.weightStart = weightOfB(a, b, t);
    step.weightHalf = weightOfB(a, b, t + 0.5 * s.h);
    step.weightFull = weightOfB(a, b, t + 1.0 * s.h);
    step.weightEnd = weightOfB(a, b, s.end);
    step.taken = 1;
    plan.ends.push_back(s.end);
    if (s.end >= options.endTime || !(s.end < until)) return plan;
    t = s.end;
  }
}

// The CPU sampler keeps each particle's last region in the snapshot (`caches`): a particle's
// consecutive samples mostly fall in one region.
void sampleSnapshot(const Snapshot& snapshot, std::span<const glm::vec3> cells,
                    std::span<RegionCache* const> caches, std::span<VectorSample> out) {
  if (snapshot.sampler) return snapshot.sampler(cells, out);
  tbb::parallel_for(std::size_t(0), cells.size(), [&](std::size_t i) {
    out[i] = sampleVector(*snapshot.volume, toCellPoint(glm::dvec3(cells[i])), caches[i]);
  });
}

}  // namespace

// The vector at (x, t) from the two snapshots bracketing t, and where each found it.
struct PathlineTracer::TimeSample {
  int reason = AMRSTREAM_REASON_RUNNING;  // OUT_OF_DOMAIN or UNEXPECTED_VALUE when it failed
  glm::vec3 value{0.0f};
  float weightB = 0.0f;
  glm::vec3 cellA{0.0f}, cellB{0.0f};
  std::int32_t regionA = -1, regionB = -1;
};

// Scratch arrays of sampleAt(), kept between calls: a batch is up to every particle, and fresh
// memory for each of the stages' batches would be paid for in page faults.
struct PathlineTracer::SampleScratch {
  std::vector<glm::vec3> cellsA, cellsB;
  std::vector<RegionCache*> cachesA, cachesB;
  std::vector<VectorSample> samplesA, samplesB;

  void resize(std::size_t n) {
    for (auto* v : {&cellsA, &cellsB}) v->resize(n);
    for (auto* v : {&cachesA, &cachesB}) v->resize(n);
    for (auto* v : {&samplesA, &samplesB}) v->resize(n);
  }
};

// The per-particle arrays of move()'s stages, kept between intervals (fresh memory for each
// would be paid for in page faults).
struct PathlineTracer::StageScratch {
  std::vector<glm::vec3> x, points, k1, k2, k3;
  std::vector<double> t, h, stageTimes;
  std::vector<char> last, goesOn;
  std::vector<int> reasons;
  std::vector<TimeSample> start, stage;

  void resize(std::size_t n) {
    for (auto* v : {&x, &points, &k1, &k2, &k3}) v->resize(std::max(v->size(), n));
    for (auto* v : {&t, &h, &stageTimes}) v->resize(std::max(v->size(), n));
    for (auto* v : {&last, &goesOn}) v->resize(std::max(v->size(), n));
    reasons.resize(std::max(reasons.size(), n));
    for (auto* v : {&start, &stage}) v->resize(std::max(v->size(), n));
  }
};

void PathlineTracer::sampleAt(const Snapshot& a, const Snapshot& b,
                              std::span<const glm::vec3> points, std::span<const double> times,
                              std::span<const std::size_t> owners, std::span<TimeSample> out) {
  SampleScratch& w = *scratch_;
  w.resize(points.size());
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
    w.cellsA[i] = cellOf(*a.volume, points[i]);
    w.cellsB[i] = cellOf(*b.volume, points[i]);
    w.cachesA[i] = &particles_[owners[i]].cacheA;
    w.cachesB[i] = &particles_[owners[i]].cacheB;
  });
  sampleSnapshot(a, w.cellsA, w.cachesA, w.samplesA);
  sampleSnapshot(b, w.cellsB, w.cachesB, w.samplesB);
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
    const VectorSample &sa = w.samplesA[i], &sb = w.samplesB[i];
    TimeSample& s = out[i];
    s = {};
    s.weightB = weightOfB(a, b, times[i]);
    s.cellA = w.cellsA[i];
    s.cellB = w.cellsB[i];
    if (!sa.located || !sb.located) {
      s.reason = AMRSTREAM_REASON_OUT_OF_DOMAIN;
      return;
    }
    if (!sa.valid || !sb.valid) {
      s.reason = AMRSTREAM_REASON_UNEXPECTED_VALUE;
      return;
    }
    // a + w (b - a): identical snapshots give a's vector exactly.
    s.value = sa.value + s.weightB * (sb.value - sa.value);
    s.regionA = sa.region;
    s.regionB = sb.region;
  });
}

PathlineTracer::PathlineTracer(std::span<const glm::dvec3> seeds, const PathlineOptions& options,
                               std::string vectorName, std::vector<std::string> channelNames)
    : options_(options),
      vectorName_(std::move(vectorName)),
      channelNames_(std::move(channelNames)),
      seedCount_(seeds.size()),
      time_(options.startTime),
      scratch_(std::make_unique<SampleScratch>()),
      stages_(std::make_unique<StageScratch>()) {
  if (!(options.stepSize > 0.0) || !std::isfinite(options.stepSize))
    throw std::invalid_argument("pathlines: the step size must be a positive number");
  if (!(options.endTime > options.startTime))
    throw std::invalid_argument("pathlines: the end time must be after the start time");
  if (options.releaseEvery > 0.0 && !std::isfinite(options.endTime))
    throw std::invalid_argument("pathlines: repeated releases need a finite end time");
  std::size_t releases = 1;
  if (options.releaseEvery > 0.0)
    releases = std::size_t(std::ceil((options.endTime - options.startTime) / options.releaseEvery));
  particles_.resize(releases * seeds.size());
  for (std::size_t r = 0; r < releases; ++r)
    for (std::size_t s = 0; s < seeds.size(); ++s) {
      Particle& p = particles_[r * seeds.size() + s];
      p.seed = std::uint32_t(s);
      p.releaseTime = options.startTime + double(r) * options.releaseEvery;
      p.position = glm::vec3(seeds[s]);
    }
}

PathlineTracer::PathlineTracer(PathlineTracer&&) noexcept = default;
PathlineTracer& PathlineTracer::operator=(PathlineTracer&&) noexcept = default;
PathlineTracer::~PathlineTracer() = default;

template <typename Needed>
void PathlineTracer::reserveRuns(std::span<const std::size_t> particles, const Needed& needed) {
  // Mostly every particle has room (storage planned, or one move's run going on): checked on all
  // cores, and only the ones that lack it listed.
  std::vector<std::uint64_t> wants(particles.size());
  tbb::parallel_for(std::size_t(0), particles.size(), [&](std::size_t k) {
    const Particle& p = particles_[particles[k]];
    const std::uint64_t want = needed(k);
    std::uint64_t left = 0;
    if (p.chunk != kNoChunk) {
      const PointChunk& c = chunks_[p.chunk];
      left = c.starts[p.run + 1] - c.starts[p.run] - c.filled[p.run];
    }
    wants[k] = left < want ? want : 0;
  });
  std::vector<std::size_t> lacking;
  std::vector<std::uint64_t> sizes;
  for (std::size_t k = 0; k < particles.size(); ++k)
    if (wants[k] > 0) {
      lacking.push_back(particles[k]);
      sizes.push_back(wants[k]);
    }
  if (lacking.empty()) return;
  const std::uint32_t index = std::uint32_t(chunks_.size());
  PointChunk& chunk = chunks_.emplace_back();
  const std::size_t runs = lacking.size();
  chunk.particles.resize(runs);
  chunk.starts.resize(runs + 1);
  chunk.filled.assign(runs, 0);
  chunk.firstPoints.resize(runs);
  chunk.starts[0] = 0;
  std::inclusive_scan(sizes.begin(), sizes.end(), chunk.starts.begin() + 1);
  tbb::parallel_for(std::size_t(0), runs, [&](std::size_t k) {
    Particle& p = particles_[lacking[k]];
    chunk.particles[k] = std::uint32_t(lacking[k]);
    chunk.firstPoints[k] = p.points;
    p.chunk = index;
    p.run = std::uint32_t(k);
  });
  const std::uint64_t slots = chunk.starts[runs];
  chunk.positions.resize(slots);
  chunk.vectors.resize(slots);
  chunk.times.resize(slots);
  chunk.channels.resize(slots * channelNames_.size());
}

float* PathlineTracer::placePoint(std::size_t particle, glm::vec3 vector) {
  Particle& p = particles_[particle];
  PointChunk& chunk = chunks_[p.chunk];
  const std::uint64_t slot = chunk.starts[p.run] + chunk.filled[p.run]++;
  chunk.positions[slot] = p.position;
  chunk.times[slot] = float(p.time);
  chunk.vectors[slot] = vector;
  p.lastChunk = p.chunk;
  p.lastSlot = slot;
  ++p.points;
  return chunk.channels.data() + slot * channelNames_.size();
}

std::uint64_t PathlineTracer::plannedSteps(std::size_t particle) {
  if (plannedTimes_.empty()) return 0;
  std::uint64_t& known = releaseSteps_[particle / std::max<std::size_t>(seedCount_, 1)];
  if (known != ~std::uint64_t(0)) return known;
  double t = particles_[particle].releaseTime;
  std::uint64_t steps = 0;
  // As advance() steps it: through each interval to its end or the end time.
  for (std::size_t i = 0; i + 1 < plannedTimes_.size() && t < options_.endTime; ++i) {
    if (plannedTimes_[i + 1] <= t) continue;
    const double until = std::min(plannedTimes_[i + 1], options_.endTime);
    steps += stepsToward(t, until, until);
    t = until;  // where the interval's last step ends
  }
  return known = steps;
}

void PathlineTracer::planStorage(std::span<const double> snapshotTimes) {
  plannedTimes_.assign(snapshotTimes.begin(), snapshotTimes.end());
  const std::size_t releases = particles_.size() / std::max<std::size_t>(seedCount_, 1);
  releaseSteps_.assign(releases, ~std::uint64_t(0));
  // The first release steps longest: a bound on every particle's points.
  const double bytes = particles_.empty()
                           ? 0.0
                           : double(particles_.size()) * double(1 + plannedSteps(0)) *
                                 double(bytesPerPoint(channelNames_.size()));
  if (options_.maxResultBytes == 0 || bytes > double(options_.maxResultBytes)) {
    plannedTimes_.clear();
    releaseSteps_.clear();
  }
}

void PathlineTracer::storePoint(std::size_t particle, const Snapshot& a, const Snapshot& b,
                                const TimeSample& s) {
  float* out = placePoint(particle, s.value);
  const std::size_t channels = channelNames_.size();
  if (channels == 0) return;
  if (s.reason != AMRSTREAM_REASON_RUNNING) {
    std::fill(out, out + channels, std::numeric_limits<float>::quiet_NaN());
    return;
  }
  thread_local std::vector<float> va, vb;
  va.resize(channels);
  vb.resize(channels);
  sampleChannels(*a.volume, s.regionA, toCellPoint(glm::dvec3(s.cellA)), va);
  sampleChannels(*b.volume, s.regionB, toCellPoint(glm::dvec3(s.cellB)), vb);
  for (std::size_t c = 0; c < channels; ++c) out[c] = va[c] + s.weightB * (vb[c] - va[c]);
}

void PathlineTracer::release(std::span<const std::size_t> due, const Snapshot& a,
                             const Snapshot& b) {
  std::vector<glm::vec3> points(due.size());
  std::vector<double> times(due.size());
  for (std::size_t i = 0; i < due.size(); ++i) {
    Particle& p = particles_[due[i]];
    p.released = true;
    p.time = p.releaseTime;
    p.position = wrapPhysical(*a.volume, p.position);
    points[i] = p.position;
    times[i] = p.time;
  }
  std::vector<TimeSample> samples(due.size());
  sampleAt(a, b, points, times, due, samples);
  std::vector<std::uint64_t> capacities(due.size());  // plannedSteps() fills its cache: in turn
  for (std::size_t k = 0; k < due.size(); ++k) capacities[k] = 1 + plannedSteps(due[k]);
  reserveRuns(due, [&](std::size_t k) { return capacities[k]; });
  tbb::parallel_for(std::size_t(0), due.size(), [&](std::size_t i) {
    storePoint(due[i], a, b, samples[i]);
    if (samples[i].reason != AMRSTREAM_REASON_RUNNING)
      particles_[due[i]].reason = samples[i].reason;
  });
}

void PathlineTracer::move(std::span<const std::size_t> moving, const Snapshot& a, const Snapshot& b,
                          double until, double reach) {
  std::vector<std::size_t> active(moving.begin(), moving.end());
  const std::size_t all = active.size();
  // Room for the steps each particle takes toward `reach`.
  std::vector<std::uint64_t> capacities(all);
  tbb::parallel_for(std::size_t(0), all, [&](std::size_t i) {
    capacities[i] = stepsToward(particles_[active[i]].time, until, reach);
  });
  reserveRuns(active, [&](std::size_t k) { return capacities[k]; });
  StageScratch& w = *stages_;
  w.resize(all);
  auto &x = w.x, &points = w.points, &k1 = w.k1, &k2 = w.k2, &k3 = w.k3;
  auto &t = w.t, &h = w.h, &stageTimes = w.stageTimes;
  auto &last = w.last, &goesOn = w.goesOn;
  auto& reasons = w.reasons;
  auto &start = w.start, &stage = w.stage;  // start: the sample at each particle's (x, t)
  bool startKnown = false;
  while (!active.empty()) {
    const std::size_t n = active.size();
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      const Particle& p = particles_[active[i]];
      x[i] = p.position;
      t[i] = p.time;
      const TimeStep step = timeStep(p.time, until, options_.stepSize);
      h[i] = step.h;
      last[i] = step.last;
    });
    const std::span<const std::size_t> owners(active.data(), n);
    if (!startKnown)
      sampleAt(a, b, std::span(x.data(), n), std::span(t.data(), n), owners,
               std::span(start.data(), n));
    // k = h v(point, time) from this stage's samples, then the next stage's point and time.
    const auto advanceStage = [&](std::vector<glm::vec3>& k, const std::vector<TimeSample>& s,
                                  float along, double timeAlong, bool first) {
      tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        k[i] = float(h[i]) * s[i].value;
        if (first || reasons[i] == AMRSTREAM_REASON_RUNNING) reasons[i] = s[i].reason;
        points[i] = x[i] + along * k[i];
        stageTimes[i] = t[i] + timeAlong * h[i];
      });
    };
    const auto sampleStage = [&] {
      sampleAt(a, b, std::span(points.data(), n), std::span(stageTimes.data(), n), owners,
               std::span(stage.data(), n));
    };
    advanceStage(k1, start, 0.5f, 0.5, true);
    sampleStage();
    advanceStage(k2, stage, 0.5f, 0.5, false);
    sampleStage();
    advanceStage(k3, stage, 1.0f, 1.0, false);
    sampleStage();
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      const glm::vec3 k4 = float(h[i]) * stage[i].value;
      if (reasons[i] == AMRSTREAM_REASON_RUNNING) reasons[i] = stage[i].reason;
      points[i] = wrapPhysical(*a.volume, x[i] + (k1[i] + 2.0f * k2[i] + 2.0f * k3[i] + k4) / 6.0f);
      stageTimes[i] = last[i] ? until : t[i] + h[i];
    });
    sampleStage();  // at the new points: their output and the next step's first stage

    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      goesOn[i] = 0;
      Particle& p = particles_[active[i]];
      const int reason = reasons[i] != AMRSTREAM_REASON_RUNNING ? reasons[i] : stage[i].reason;
      if (reason != AMRSTREAM_REASON_RUNNING) {
        p.reason = reason;
        return;
      }
      p.position = points[i];
      p.time = stageTimes[i];
      ++p.steps;
      storePoint(active[i], a, b, stage[i]);
      if (p.time >= options_.endTime) {
        p.reason = options_.endReason;
        return;
      }
      goesOn[i] = stepsBy(p.time, until, reach);
    });
    // Mostly every particle goes on (all but the interval's last step): no copying then.
    const std::size_t going = std::size_t(std::count(goesOn.begin(), goesOn.begin() + n, 1));
    if (going == n) {
      std::swap(start, stage);
    } else {
      std::size_t kept = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (goesOn[i]) {
          active[kept] = active[i];
          start[kept] = stage[i];
          ++kept;
        }
      active.resize(kept);
    }
    startKnown = true;
  }
}

void PathlineTracer::moveOnDevice(std::span<const std::size_t> moving, const Snapshot& a,
                                  const Snapshot& b, double until, double reach,
                                  IntervalStepper& stepper) {
  const std::size_t n = moving.size();
  if (n == 0) return;
  // Particles at one time take the same steps: one group each.
  // The particles' states gathered on all cores (they lie in Morton order, scattered in memory).
  std::map<double, std::uint32_t> groupOfTime;
  std::vector<std::uint32_t> groups(n);
  std::vector<glm::vec3> positions(n);
  std::vector<double> times(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    const Particle& p = particles_[moving[i]];
    positions[i] = p.position;
    times[i] = p.time;
  });
  double lastTime = std::numeric_limits<double>::quiet_NaN();
  std::uint32_t lastGroup = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(times[i] == lastTime)) {  // mostly every particle is at one time
      lastTime = times[i];
      lastGroup =
          groupOfTime.try_emplace(times[i], std::uint32_t(groupOfTime.size())).first->second;
    }
    groups[i] = lastGroup;
  }
  std::vector<GroupSteps> plans(groupOfTime.size());
  std::size_t stepCount = 0;
  for (const auto& [time, group] : groupOfTime) {
    plans[group] = planSteps(time, until, reach, options_, a, b);
    stepCount = std::max(stepCount, plans[group].steps.size());
  }
  std::vector<shared::PathlineStep> schedule(plans.size() * stepCount, shared::PathlineStep{});
  for (std::size_t g = 0; g < plans.size(); ++g)
    std::copy(plans[g].steps.begin(), plans[g].steps.end(), schedule.begin() + g * stepCount);

  const IntervalPlan plan{positions, groups, schedule, std::uint32_t(stepCount)};
  reserveRuns(moving, [&](std::size_t k) { return plans[groups[k]].steps.size(); });
  // What storing a step needs of each particle, in the order of the rows (the particles
  // themselves lie scattered in memory): its next slot, whether it runs, its last step. Written
  // back to the particles once the interval's rounds are stored.
  struct Cursor {
    PointChunk* chunk;
    std::uint64_t slot;
    std::uint32_t stored = 0;
    std::uint32_t lastStep = 0;
    int reason;
  };
  std::vector<Cursor> cursors(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    const Particle& p = particles_[moving[i]];
    PointChunk& chunk = chunks_[p.chunk];
    cursors[i] = {&chunk, chunk.starts[p.run] + chunk.filled[p.run], 0, 0, p.reason};
  });
  stepper.move(plan, [&](const StepRows& rows) {
    if (rows.channelCount != channelNames_.size())
      throw std::logic_error("pathlines: the device sampled other point-data channels");
    const std::size_t channels = rows.channelCount;
    // A tile of particles at a time, step by step: the rows are read in order and each
    // particle's points go to its run, in order.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
      for (std::uint32_t r = 0; r < rows.rows; ++r)
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
          Cursor& c = cursors[i];
          const std::size_t at = std::size_t(r) * n + i;
          const std::int32_t status = rows.status[at];
          if (status == AMRSTREAM_PATHLINE_NO_STEP || c.reason != AMRSTREAM_REASON_RUNNING)
            continue;
          if (status != AMRSTREAM_REASON_RUNNING) {
            c.reason = status;
            continue;
          }
          const GroupSteps& steps = plans[groups[i]];
          const std::uint32_t step = rows.firstStep + r;
          const std::uint64_t slot = c.slot++;
          PointChunk& chunk = *c.chunk;
          chunk.positions[slot] = rows.positions[at];
          chunk.times[slot] = float(steps.ends[step]);
          chunk.vectors[slot] = rows.vectors[at];
          ++c.stored;
          c.lastStep = step;
          float* out = chunk.channels.data() + slot * channels;
          const float w = steps.steps[step].weightEnd;
          for (std::size_t k = 0; k < channels; ++k) {
            const float va = rows.channelsA[at * channels + k];
            const float vb = rows.channelsB[at * channels + k];
            out[k] = va + w * (vb - va);  // as storePoint() blends them
          }
          if (steps.ends[step] >= options_.endTime) c.reason = options_.endReason;
        }
    });
  });
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    const Cursor& c = cursors[i];
    Particle& p = particles_[moving[i]];
    p.reason = c.reason;
    if (c.stored == 0) return;
    const std::uint64_t last = c.slot - 1;
    p.position = c.chunk->positions[last];
    p.time = plans[groups[i]].ends[c.lastStep];
    p.steps += c.stored;
    p.points += c.stored;
    c.chunk->filled[p.run] += c.stored;
    p.lastChunk = p.chunk;
    p.lastSlot = last;
  });
}

void PathlineTracer::advance(Snapshot a, Snapshot b, IntervalStepper* stepper, double stopAt) {
  if (!(b.time > a.time))
    throw std::invalid_argument("pathlines: an interval must go forward in time");
  for (const Snapshot* s : {&a, &b}) {
    if (s->volume->channelNames != channelNames_)
      throw std::invalid_argument("pathlines: every snapshot needs the same point-data channels");
    if (s->volume->deepPositions())
      throw InputError("pathlines",
                       "a snapshot spans more than 2^21 finest cells on an axis; "
                       "pathlines keep float positions, which cannot resolve its "
                       "finest cells (streamlines with `trace` can)");
  }
  const double until = std::min(b.time, options_.endTime);
  const double reach = std::min(until, stopAt);
  // The caches hold regions of the volumes they name.
  const bool sameInterval = a.volume == lastA_ && b.volume == lastB_;
  const bool aWasB = a.volume == lastB_;
  tbb::parallel_for(std::size_t(0), particles_.size(), [&](std::size_t i) {
    Particle& p = particles_[i];
    if (!sameInterval) {
      p.cacheA = aWasB ? p.cacheB : RegionCache{};
      p.cacheB = {};
    }
    p.pointsBefore = p.points;
  });
  lastA_ = a.volume;
  lastB_ = b.volume;
  std::vector<std::size_t> due, moving;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const Particle& p = particles_[i];
    if (!p.released && p.releaseTime >= a.time && p.releaseTime < reach) due.push_back(i);
  }
  release(due, a, b);
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const Particle& p = particles_[i];
    if (p.released && p.reason == AMRSTREAM_REASON_RUNNING && stepsBy(p.time, until, reach))
      moving.push_back(i);
  }
  if (stepper) {
    // Neighbouring threads start near each other, and mostly stay so through the interval and
    // the next: the particles are sorted again only when others join.
    std::vector<char> stays(deviceOrder_.size());
    tbb::parallel_for(std::size_t(0), deviceOrder_.size(), [&](std::size_t k) {
      const Particle& p = particles_[deviceOrder_[k]];
      stays[k] = p.reason == AMRSTREAM_REASON_RUNNING && stepsBy(p.time, until, reach);
    });
    std::size_t kept = 0;
    for (std::size_t k = 0; k < deviceOrder_.size(); ++k)
      if (stays[k]) deviceOrder_[kept++] = deviceOrder_[k];
    deviceOrder_.resize(kept);
    if (!due.empty() || deviceOrder_.size() != moving.size()) {
      std::vector<glm::vec3> starts(moving.size());
      for (std::size_t i = 0; i < moving.size(); ++i) starts[i] = particles_[moving[i]].position;
      const std::vector<std::uint32_t> order = mortonOrder(starts);
      deviceOrder_.resize(moving.size());
      for (std::size_t i = 0; i < order.size(); ++i) deviceOrder_[i] = moving[order[i]];
    }
    moving = deviceOrder_;
    const std::size_t most = stepper->mostParticles();
    for (std::size_t first = 0; first < moving.size(); first += most)
      moveOnDevice(std::span(moving).subspan(first, std::min(most, moving.size() - first)), a, b,
                   until, reach, *stepper);
  } else
    move(moving, a, b, until, reach);
  time_ = reach;
  if (options_.maxResultBytes > 0) {
    const std::uint64_t bytes = pointCount() * TraceSet::bytesPerPoint(channelNames_.size(), false);
    if (bytes > options_.maxResultBytes)
      throw InputError("pathlines",
                       fmt::format("the paths take {:.2f} GB by time {}, more than the limit of "
                                   "{:.2f} GB: use fewer seeds, a longer step or a shorter span",
                                   bytes / 1e9, reach, options_.maxResultBytes / 1e9));
  }
}

bool PathlineTracer::stepsBy(double t, double until, double reach) const {
  return t < until && endsBy(timeStep(t, until, options_.stepSize), reach, options_.stepSize);
}

std::uint64_t PathlineTracer::stepsToward(double t, double until, double reach) const {
  std::uint64_t steps = 0;
  for (; t < options_.endTime && stepsBy(t, until, reach); ++steps)
    t = timeStep(t, until, options_.stepSize).end;
  return steps;
}

void PathlineTracer::finish() {
  for (Particle& p : particles_)
    if (p.released && p.reason == AMRSTREAM_REASON_RUNNING) p.reason = AMRSTREAM_REASON_SERIES_END;
}

std::vector<std::int32_t> PathlineTracer::reasons() const {
  std::vector<std::int32_t> reasons;
  for (const Particle& p : particles_)
    if (p.released) reasons.push_back(p.reason);
  return reasons;
}

std::uint64_t PathlineTracer::pointCount() const {
  std::uint64_t points = 0;
  for (const Particle& p : particles_) points += p.points;
  return points;
}

std::uint64_t PathlineTracer::stepCount() const {
  std::uint64_t steps = 0;
  for (const Particle& p : particles_) steps += p.steps;
  return steps;
}

std::size_t PathlineTracer::runningCount() const {
  return std::size_t(std::count_if(particles_.begin(), particles_.end(), [](const Particle& p) {
    return p.released && p.reason == AMRSTREAM_REASON_RUNNING;
  }));
}

TraceSet PathlineTracer::emptySet() const {
  TraceSet set;
  set.vectorName = vectorName_;
  set.channelNames = channelNames_;
  return set;
}

TraceSet PathlineTracer::pathlines() const { return assemble(false); }

TraceSet PathlineTracer::lastGrowth() const { return assemble(true); }

TraceSet PathlineTracer::lineFrame(std::span<const std::uint32_t> from,
                                   std::span<std::uint64_t> start) const {
  TraceSet set = emptySet();
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const Particle& p = particles_[i];
    if (!p.released || from[i] > p.points) continue;
    start[i] = set.offsets.back();
    set.seedIds.push_back(p.seed);
    set.directions.push_back(1.0f);
    set.steps.push_back(p.steps);
    set.reasons.push_back(p.reason);
    set.offsets.push_back(start[i] + (p.points - from[i]));
  }
  return set;
}

TraceSet PathlineTracer::assemble(bool growth) const {
  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> from(particles_.size(), growth ? kNone : 0);
  if (growth)
    for (std::size_t i = 0; i < particles_.size(); ++i) {
      const Particle& p = particles_[i];
      if (p.points > p.pointsBefore) from[i] = p.pointsBefore > 0 ? p.pointsBefore - 1 : 0;
    }
  std::vector<std::uint64_t> start(particles_.size());
  TraceSet set = lineFrame(from, start);
  const std::size_t channels = channelNames_.size();
  const std::uint64_t points = set.pointCount();
  set.positions.resize(points);
  set.times.resize(points);
  set.vectors.resize(points);
  set.channels.resize(points * channels);
  // Each run's points that the lines take, copied whole: a particle's runs hold its points in
  // order, so a chunk's runs go in parallel.
  for (const PointChunk& chunk : chunks_)
    tbb::parallel_for(std::size_t(0), chunk.particles.size(), [&](std::size_t k) {
      const std::uint32_t particle = chunk.particles[k];
      const std::uint64_t first = chunk.firstPoints[k], end = first + chunk.filled[k];
      const std::uint64_t lo = std::max<std::uint64_t>(first, from[particle]);
      if (from[particle] == kNone || lo >= end) return;
      const std::uint64_t slot = chunk.starts[k] + (lo - first), count = end - lo;
      const std::uint64_t at = start[particle] + (lo - from[particle]);
      std::copy_n(chunk.positions.begin() + slot, count, set.positions.begin() + at);
      std::copy_n(chunk.times.begin() + slot, count, set.times.begin() + at);
      std::copy_n(chunk.vectors.begin() + slot, count, set.vectors.begin() + at);
      std::copy_n(chunk.channels.begin() + slot * channels, count * channels,
                  set.channels.begin() + at * channels);
    });
  return set;
}

TraceSet PathlineTracer::takePathlines() && {
  const std::size_t released = std::size_t(std::count_if(
      particles_.begin(), particles_.end(), [](const Particle& p) { return p.released; }));
  if (chunks_.size() != 1 || chunks_[0].particles.size() != released) return pathlines();
  // One chunk with a run per released particle, in order: its runs close up in place, each
  // column on its own core, and become the lines.
  PointChunk& chunk = chunks_[0];
  const std::vector<std::uint32_t> from(particles_.size(), 0);
  std::vector<std::uint64_t> start(particles_.size());
  TraceSet set = lineFrame(from, start);
  const auto closeUp = [&](auto& column, std::size_t width) {
    for (std::size_t k = 0; k < chunk.particles.size(); ++k) {
      const std::uint64_t slot = chunk.starts[k] * width, at = start[chunk.particles[k]] * width;
      if (slot != at)  // at < slot: a forward copy is safe
        std::copy_n(column.begin() + slot, chunk.filled[k] * width, column.begin() + at);
    }
    column.resize(set.pointCount() * width);
  };
  tbb::parallel_invoke([&] { closeUp(chunk.positions, 1); }, [&] { closeUp(chunk.times, 1); },
                       [&] { closeUp(chunk.vectors, 1); },
                       [&] { closeUp(chunk.channels, channelNames_.size()); });
  set.positions = std::move(chunk.positions);
  set.times = std::move(chunk.times);
  set.vectors = std::move(chunk.vectors);
  set.channels = std::move(chunk.channels);
  chunks_.clear();
  return set;
}

TraceSet PathlineTracer::streaklines() const {
  TraceSet set = emptySet();
  set.timesAreAges = true;
  const std::size_t channels = channelNames_.size();
  const std::size_t releases = seedCount_ == 0 ? 0 : particles_.size() / seedCount_;
  std::uint64_t at = 0;
  for (std::size_t s = 0; s < seedCount_; ++s) {
    std::uint32_t count = 0;
    int reason = AMRSTREAM_REASON_RUNNING;
    for (std::size_t r = releases; r-- > 0;) {
      const Particle& p = particles_[r * seedCount_ + s];
      if (!p.released || p.time < time_) continue;  // not yet released, or stopped before the end
      reason = p.reason;
      const PointChunk& chunk = chunks_[p.lastChunk];
      set.positions.push_back(chunk.positions[p.lastSlot]);
      set.times.push_back(float(p.time - p.releaseTime));
      set.vectors.push_back(chunk.vectors[p.lastSlot]);
      for (std::size_t c = 0; c < channels; ++c)
        set.channels.push_back(chunk.channels[p.lastSlot * channels + c]);
      ++at;
      ++count;
    }
    if (count == 0) continue;
    set.seedIds.push_back(std::uint32_t(s));
    set.directions.push_back(1.0f);
    set.steps.push_back(count - 1);
    set.reasons.push_back(reason);
    set.offsets.push_back(at);
  }
  return set;
}

}  // namespace amrstream::flow
