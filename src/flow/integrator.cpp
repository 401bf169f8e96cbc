#include "integrator.hpp"

#include <tbb/parallel_for.h>

#include <atomic>

#include "sampler.hpp"

namespace amrstream::flow {

namespace {

// Positions are integrated in finest-cell units; velocities and cell widths are physical.
// parameterStep() is the advance of IntegrationTime (physical time, or physical arc length in arc
// mode) and direction() the RK4 stage vector in cell units; both read the same TraceParams
// values as their GLSL twins in shaders/glsl/include/integrator.glsl.
float parameterStep(const shared::TraceParams& params, const VectorSample& s) {
  return params.stepMode == AMRSTREAM_STEP_TIME
             ? params.stepSize
             : params.stepSize * s.cellWidth * params.physicalCellWidth;
}

glm::vec3 direction(const shared::TraceParams& params, const VectorSample& s) {
  glm::vec3 v = s.value;
  if (params.stepMode == AMRSTREAM_STEP_ARC) {
    const float speed = glm::length(v);
    v = speed > 0.0f ? v / speed : glm::vec3(0.0f);
  }
  return parameterStep(params, s) * v * params.cellsPerPhysical;
}

// The reason a stage sample ends the trace, or AMRSTREAM_REASON_RUNNING.
int sampleFailure(const VectorSample& s) {
  if (!s.located) return AMRSTREAM_REASON_OUT_OF_DOMAIN;
  if (!s.valid) return AMRSTREAM_REASON_UNEXPECTED_VALUE;
  return AMRSTREAM_REASON_RUNNING;
}

void traceSeed(const VectorVolume& volume, glm::vec3 seed, const shared::TraceParams& params,
               TraceSet& out, std::uint32_t seedIndex) {
  const glm::dvec3 origin = volume.transform.origin, spacing = volume.transform.spacing;
  glm::vec3 x = seed;
  RegionCache cache;
  VectorSample s = sampleVector(volume, x, &cache);
  float time = 0.0f, length = 0.0f;
  std::uint32_t points = 0;
  // Without history every point overwrites slot 0, so the last point remains.
  const auto append = [&](glm::vec3 position, const VectorSample& sample) {
    const std::size_t at = out.at(seedIndex, params.keepHistory ? points : 0);
    ++points;
    out.positions[at] = glm::vec3(origin + spacing * glm::dvec3(position));
    out.times[at] = time;
    out.vectors[at] = sample.value;
  };
  append(x, s);

  int reason = sampleFailure(s);
  for (std::uint32_t step = 0; reason == AMRSTREAM_REASON_RUNNING; ++step) {
    if (glm::length(s.value) < params.terminalSpeed) {
      reason = AMRSTREAM_REASON_STAGNATION;
      break;
    }
    if (step == params.maxSteps) {
      reason = AMRSTREAM_REASON_MAX_STEPS;
      break;
    }
    const glm::vec3 k1 = direction(params, s);
    const VectorSample s2 = sampleVector(volume, x + 0.5f * k1, &cache);
    if ((reason = sampleFailure(s2))) break;
    const glm::vec3 k2 = direction(params, s2);
    const VectorSample s3 = sampleVector(volume, x + 0.5f * k2, &cache);
    if ((reason = sampleFailure(s3))) break;
    const glm::vec3 k3 = direction(params, s3);
    const VectorSample s4 = sampleVector(volume, x + k3, &cache);
    if ((reason = sampleFailure(s4))) break;
    const glm::vec3 k4 = direction(params, s4);
    const glm::vec3 next = x + (k1 + 2.0f * k2 + 2.0f * k3 + k4) / 6.0f;
    const VectorSample sNext = sampleVector(volume, next, &cache);
    if ((reason = sampleFailure(sNext))) break;

    if (params.maxLength > 0.0f) {
      const float stepLength = glm::length(params.spacing * (next - x));
      if (length + stepLength > params.maxLength) {
        reason = AMRSTREAM_REASON_MAX_LENGTH;
        break;
      }
      length += stepLength;
    }
    time += parameterStep(params, s);
    x = next;
    s = sNext;
    append(x, s);
  }
  out.pointCounts[seedIndex] = params.keepHistory ? points : 1;
  out.steps[seedIndex] = points - 1;
  out.reasons[seedIndex] = reason;
}

}  // namespace

shared::TraceParams makeTraceParams(const VectorVolume& volume, const TraceOptions& options,
                                    std::size_t seedCount) {
  const glm::dvec3 spacing = volume.transform.spacing;
  shared::TraceParams params{};
  params.domainLower = volume.domain.lower;
  params.domainUpper = volume.domain.upper;
  params.seedCount = static_cast<std::uint32_t>(seedCount);
  params.capacity = options.keepHistory ? options.maxSteps + 1 : 1;
  params.cellsPerPhysical = glm::vec3(1.0 / spacing);
  params.physicalCellWidth = float(glm::min(spacing.x, glm::min(spacing.y, spacing.z)));
  params.spacing = glm::vec3(spacing);
  params.stepMode = static_cast<int>(options.stepMode);
  params.stepSize = options.stepSize;
  params.maxSteps = options.maxSteps;
  params.terminalSpeed = options.terminalSpeed;
  params.maxLength = options.maxLength;
  params.keepHistory = options.keepHistory ? 1u : 0u;
  return params;
}

TraceSet traceStreamlines(const VectorVolume& volume, std::span<const glm::dvec3> seeds,
                          const TraceOptions& options,
                          const std::function<void(std::size_t)>& progress) {
  const shared::TraceParams params = makeTraceParams(volume, options, seeds.size());
  TraceSet out;
  out.resize(static_cast<std::uint32_t>(seeds.size()), params.capacity);
  out.vectorName = volume.vectorName;

  std::atomic<std::size_t> finished{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, seeds.size(), 16), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const glm::vec3 seed(volume.transform.toCellUnits(seeds[i]));
      traceSeed(volume, seed, params, out, static_cast<std::uint32_t>(i));
    }
    const std::size_t done = finished += range.size();
    if (progress) progress(done);
  });
  return out;
}

}  // namespace amrstream::flow
