#include "pathline_tracer.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "sampler.hpp"
#include "util/input_error.hpp"

namespace amrstream::flow {

namespace {

// A step this much shorter than dt that would be left before an interval's end is taken with
// the step before it: float rounding of the time must not make a sliver of a step.
constexpr double kSliverFraction = 1e-4;

// The vector at (x, t) from the two snapshots bracketing t, with the regions each was found in.
struct TimeSample {
  int reason = AMRSTREAM_REASON_RUNNING;  // OUT_OF_DOMAIN or UNEXPECTED_VALUE when it failed
  glm::vec3 value{0.0f};
  float weightB = 0.0f;
  glm::vec3 cellA{0.0f}, cellB{0.0f};
  std::int32_t regionA = -1, regionB = -1;
};

struct Caches {
  RegionCache a, b;
};

glm::vec3 cellOf(const VectorVolume& volume, glm::vec3 x) {
  return wrapPeriodic(volume, glm::vec3(volume.transform.toCellUnits(glm::dvec3(x))));
}

// x moved by whole periods into a's domain along its periodic axes.
glm::vec3 wrapPhysical(const VectorVolume& volume, glm::vec3 x) {
  if (!(volume.periodic[0] || volume.periodic[1] || volume.periodic[2])) return x;
  return glm::vec3(volume.transform.toPhysical(glm::dvec3(cellOf(volume, x))));
}

TimeSample sampleAt(Snapshot a, Snapshot b, glm::vec3 x, double t, Caches& caches) {
  TimeSample s;
  s.weightB = float((t - a.time) / (b.time - a.time));
  s.cellA = cellOf(*a.volume, x);
  s.cellB = cellOf(*b.volume, x);
  const VectorSample sa = sampleVector(*a.volume, s.cellA, &caches.a);
  const VectorSample sb = sampleVector(*b.volume, s.cellB, &caches.b);
  if (!sa.located || !sb.located) {
    s.reason = AMRSTREAM_REASON_OUT_OF_DOMAIN;
    return s;
  }
  if (!sa.valid || !sb.valid) {
    s.reason = AMRSTREAM_REASON_UNEXPECTED_VALUE;
    return s;
  }
  // a + w (b - a): identical snapshots give a's vector exactly.
  s.value = sa.value + s.weightB * (sb.value - sa.value);
  s.regionA = sa.region;
  s.regionB = sb.region;
  return s;
}

}  // namespace

PathlineTracer::PathlineTracer(std::span<const glm::dvec3> seeds, const PathlineOptions& options,
                               std::string vectorName, std::vector<std::string> channelNames)
    : options_(options),
      vectorName_(std::move(vectorName)),
      channelNames_(std::move(channelNames)),
      seedCount_(seeds.size()),
      time_(options.startTime) {
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

void PathlineTracer::release(Particle& p, Snapshot a, Snapshot b) const {
  p.released = true;
  p.time = p.releaseTime;
  Caches caches;
  const TimeSample s = sampleAt(a, b, p.position, p.time, caches);
  p.position = wrapPhysical(*a.volume, p.position);
  p.positions.push_back(p.position);
  p.times.push_back(p.time);
  p.vectors.push_back(s.value);
  const std::size_t channels = channelNames_.size();
  p.channels.resize(channels, std::numeric_limits<float>::quiet_NaN());
  if (s.reason != AMRSTREAM_REASON_RUNNING) {
    p.reason = s.reason;
    return;
  }
  if (channels > 0) {
    std::vector<float> va(channels), vb(channels);
    sampleChannels(*a.volume, s.regionA, s.cellA, va);
    sampleChannels(*b.volume, s.regionB, s.cellB, vb);
    for (std::size_t c = 0; c < channels; ++c) p.channels[c] = va[c] + s.weightB * (vb[c] - va[c]);
  }
}

void PathlineTracer::move(Particle& p, Snapshot a, Snapshot b, double until) const {
  const std::size_t channels = channelNames_.size();
  std::vector<float> va(channels), vb(channels);
  Caches caches;
  while (p.reason == AMRSTREAM_REASON_RUNNING && p.time < until) {
    double h = std::min(options_.stepSize, until - p.time);
    const bool last = until - (p.time + h) < kSliverFraction * options_.stepSize;
    if (last) h = until - p.time;
    const float hf = float(h);
    const glm::vec3 x = p.position;
    const TimeSample s1 = sampleAt(a, b, x, p.time, caches);
    int reason = s1.reason;
    TimeSample s2, s3, s4, next;
    glm::vec3 moved{0.0f};
    if (reason == AMRSTREAM_REASON_RUNNING) {
      const glm::vec3 k1 = hf * s1.value;
      s2 = sampleAt(a, b, x + 0.5f * k1, p.time + 0.5 * h, caches);
      reason = s2.reason;
      if (reason == AMRSTREAM_REASON_RUNNING) {
        const glm::vec3 k2 = hf * s2.value;
        s3 = sampleAt(a, b, x + 0.5f * k2, p.time + 0.5 * h, caches);
        reason = s3.reason;
        if (reason == AMRSTREAM_REASON_RUNNING) {
          const glm::vec3 k3 = hf * s3.value;
          s4 = sampleAt(a, b, x + k3, p.time + h, caches);
          reason = s4.reason;
          if (reason == AMRSTREAM_REASON_RUNNING) {
            const glm::vec3 k4 = hf * s4.value;
            moved = wrapPhysical(*a.volume, x + (k1 + 2.0f * k2 + 2.0f * k3 + k4) / 6.0f);
            next = sampleAt(a, b, moved, p.time + h, caches);
            reason = next.reason;
          }
        }
      }
    }
    if (reason != AMRSTREAM_REASON_RUNNING) {
      p.reason = reason;
      return;
    }
    p.position = moved;
    p.time = last ? until : p.time + h;
    ++p.steps;
    p.positions.push_back(p.position);
    p.times.push_back(p.time);
    p.vectors.push_back(next.value);
    if (channels > 0) {
      sampleChannels(*a.volume, next.regionA, next.cellA, va);
      sampleChannels(*b.volume, next.regionB, next.cellB, vb);
      for (std::size_t c = 0; c < channels; ++c)
        p.channels.push_back(va[c] + next.weightB * (vb[c] - va[c]));
    }
  }
  if (p.reason == AMRSTREAM_REASON_RUNNING && p.time >= options_.endTime)
    p.reason = options_.endReason;
}

void PathlineTracer::advance(Snapshot a, Snapshot b) {
  if (!(b.time > a.time))
    throw std::invalid_argument("pathlines: an interval must go forward in time");
  for (const Snapshot& s : {a, b})
    if (s.volume->channelNames != channelNames_)
      throw std::invalid_argument("pathlines: every snapshot needs the same point-data channels");
  const double until = std::min(b.time, options_.endTime);
  tbb::parallel_for(std::size_t(0), particles_.size(), [&](std::size_t i) {
    Particle& p = particles_[i];
    if (!p.released) {
      if (p.releaseTime < a.time || p.releaseTime >= until) return;
      release(p, a, b);
    }
    if (p.reason == AMRSTREAM_REASON_RUNNING) move(p, a, b, until);
  });
  time_ = until;
  if (options_.maxResultBytes > 0) {
    const std::uint64_t bytes =
        pointCount() * TraceSet::bytesPerPoint(channelNames_.size(), false);
    if (bytes > options_.maxResultBytes)
      throw InputError("pathlines",
                       fmt::format("the paths take {:.2f} GB by time {}, more than the limit of "
                                   "{:.2f} GB: use fewer seeds, a longer step or a shorter span",
                                   bytes / 1e9, until, options_.maxResultBytes / 1e9));
  }
}

void PathlineTracer::finish() {
  for (Particle& p : particles_)
    if (p.released && p.reason == AMRSTREAM_REASON_RUNNING) p.reason = AMRSTREAM_REASON_SERIES_END;
}

std::size_t PathlineTracer::runningCount() const {
  return std::size_t(std::count_if(particles_.begin(), particles_.end(), [](const Particle& p) {
    return p.released && p.reason == AMRSTREAM_REASON_RUNNING;
  }));
}

std::uint64_t PathlineTracer::pointCount() const {
  std::uint64_t points = 0;
  for (const Particle& p : particles_) points += p.positions.size();
  return points;
}

std::uint64_t PathlineTracer::stepCount() const {
  std::uint64_t steps = 0;
  for (const Particle& p : particles_) steps += p.steps;
  return steps;
}

TraceSet PathlineTracer::emptySet() const {
  TraceSet set;
  set.vectorName = vectorName_;
  set.channelNames = channelNames_;
  return set;
}

TraceSet PathlineTracer::pathlines() const {
  TraceSet set = emptySet();
  const std::uint64_t points = pointCount();
  const std::size_t channels = channelNames_.size();
  set.positions.resize(points);
  set.times.resize(points);
  set.vectors.resize(points);
  set.channels.resize(points * channels);
  std::uint64_t at = 0;
  for (const Particle& p : particles_) {
    if (!p.released) continue;
    set.seedIds.push_back(p.seed);
    set.directions.push_back(1.0f);
    set.steps.push_back(p.steps);
    set.reasons.push_back(p.reason);
    for (std::size_t k = 0; k < p.positions.size(); ++k, ++at) {
      set.positions[at] = p.positions[k];
      set.times[at] = float(p.times[k]);
      set.vectors[at] = p.vectors[k];
      for (std::size_t c = 0; c < channels; ++c)
        set.channels[at * channels + c] = p.channels[k * channels + c];
    }
    set.offsets.push_back(at);
  }
  return set;
}

TraceSet PathlineTracer::streaklines() const {
  TraceSet set = emptySet();
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
      set.positions.push_back(p.positions.back());
      set.times.push_back(float(p.time - p.releaseTime));
      set.vectors.push_back(p.vectors.back());
      for (std::size_t c = 0; c < channels; ++c)
        set.channels.push_back(p.channels[(p.positions.size() - 1) * channels + c]);
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
