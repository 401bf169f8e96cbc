#include "line_tracer.hpp"

#include <cmath>

#include "../../shaders/glsl/shared/trace_codes.h"

namespace amrstream::flow {

namespace {

// Positions are integrated in finest-cell units; velocities and cell widths are physical.
// parameterStep() is the advance of |IntegrationTime| (physical time, or physical arc length in
// arc mode) and direction() the RK4 stage vector in cell units; both read the same TraceParams
// values as their GLSL twins.
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

// wrapPeriodic() with the round's parameters, as the kernels do it.
glm::vec3 wrap(const shared::TraceParams& params, glm::vec3 p) {
  for (int a = 0; a < 3; ++a) {
    if ((params.periodicAxes & (1u << a)) == 0) continue;
    const float lower = float(params.domainLower[a]), upper = float(params.domainUpper[a]);
    if (p[a] >= upper)
      p[a] -= params.period[a];
    else if (p[a] < lower)
      p[a] += params.period[a];
    if (p[a] >= upper) p[a] = lower;
  }
  return p;
}

}  // namespace

shared::LineRound advanceLine(const VectorVolume& volume, const shared::TraceParams& params,
                              shared::LineState& state, const PointEmitter& emit) {
  RegionCache cache;
  const auto sample = [&](glm::vec3 p) { return sampleVector(volume, wrap(params, p), &cache); };
  const float sign = state.direction;
  glm::vec3 x = state.position;
  float time = state.time, length = state.arcLength;
  std::uint32_t steps = state.steps, emitted = 0;
  VectorSample s = sample(x);
  if (steps == 0 && params.keepHistory) {
    emit(x, time, s);
    ++emitted;
  }

  int reason = sampleFailure(s);
  for (std::uint32_t taken = 0; reason == AMRSTREAM_REASON_RUNNING; ++taken) {
    if (glm::length(s.value) < params.terminalSpeed) {
      reason = AMRSTREAM_REASON_STAGNATION;
      break;
    }
    if (steps == params.maxSteps) {
      reason = AMRSTREAM_REASON_MAX_STEPS;
      break;
    }
    if (params.maxTime > 0.0f && std::abs(time) >= params.maxTime) {
      reason = AMRSTREAM_REASON_MAX_TIME;
      break;
    }
    if (taken == params.roundSteps) break;  // paused; the next round goes on from here

    // The last step before --max-time is shortened to end on it.
    const float advance = parameterStep(params, s);
    float scale = sign;
    const bool endsOnMaxTime = params.maxTime > 0.0f && std::abs(time) + advance > params.maxTime;
    if (endsOnMaxTime) scale = sign * ((params.maxTime - std::abs(time)) / advance);

    const glm::vec3 k1 = scale * direction(params, s);
    const VectorSample s2 = sample(x + 0.5f * k1);
    if ((reason = sampleFailure(s2))) break;
    const glm::vec3 k2 = scale * direction(params, s2);
    const VectorSample s3 = sample(x + 0.5f * k2);
    if ((reason = sampleFailure(s3))) break;
    const glm::vec3 k3 = scale * direction(params, s3);
    const VectorSample s4 = sample(x + k3);
    if ((reason = sampleFailure(s4))) break;
    const glm::vec3 k4 = scale * direction(params, s4);
    const glm::vec3 unwrapped = x + (k1 + 2.0f * k2 + 2.0f * k3 + k4) / 6.0f;
    const glm::vec3 next = wrap(params, unwrapped);
    const VectorSample sNext = sampleVector(volume, next, &cache);
    if ((reason = sampleFailure(sNext))) break;

    if (params.maxLength > 0.0f) {
      const float stepLength = glm::length(params.spacing * (unwrapped - x));
      if (length + stepLength > params.maxLength) {
        reason = AMRSTREAM_REASON_MAX_LENGTH;
        break;
      }
      length += stepLength;
    }
    time = endsOnMaxTime ? sign * params.maxTime : time + sign * advance;
    x = next;
    s = sNext;
    ++steps;
    if (params.keepHistory) {
      emit(x, time, s);
      ++emitted;
    }
  }
  if (!params.keepHistory && reason != AMRSTREAM_REASON_RUNNING) {
    emit(x, time, s);
    ++emitted;
  }
  state = {x, time, length, steps, state.line, sign};
  return {state.line, emitted, steps, reason};
}

}  // namespace amrstream::flow
