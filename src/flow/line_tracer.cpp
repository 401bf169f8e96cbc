#include "line_tracer.hpp"

#include <cmath>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "line_steps.hpp"
#include "trace_options.hpp"

namespace amrstream::flow {

namespace {

// Positions are integrated in finest-cell units; velocities and cell widths are physical.
// parameterStep() is the advance of |IntegrationTime| (physical time, or physical arc length in
// arc mode) and direction() the RK4 stage vector in cell units; both read the same TraceParams
// values as their GLSL twins.
float parameterStep(const shared::TraceParams& params, const VectorSample& s, float h) {
  return params.stepMode == AMRSTREAM_STEP_TIME ? h : h * s.cellWidth * params.physicalCellWidth;
}

glm::vec3 direction(const shared::TraceParams& params, const VectorSample& s, float h) {
  glm::vec3 v = s.value;
  if (params.stepMode == AMRSTREAM_STEP_ARC) {
    const float speed = glm::length(v);
    v = speed > 0.0f ? v / speed : glm::vec3(0.0f);
  }
  return parameterStep(params, s, h) * v * params.cellsPerPhysical;
}

// The reason a stage sample ends the trace, or AMRSTREAM_REASON_RUNNING.
int sampleFailure(const VectorSample& s) {
  if (!s.located) return AMRSTREAM_REASON_OUT_OF_DOMAIN;
  if (!s.valid) return AMRSTREAM_REASON_UNEXPECTED_VALUE;
  return AMRSTREAM_REASON_RUNNING;
}

// Without deep positions the anchor stays zero, and a point that leaves the domain along a
// periodic axis moves by the period in float; twin of wrapCellUnits() in line_round.glsl.
glm::vec3 wrapCellUnits(const shared::TraceParams& params, glm::vec3 p) {
  for (int a = 0; a < 3; ++a) {
    if ((params.periodicAxes & (1u << a)) == 0) continue;
    const float lower = float(params.domainLower[a]), upper = float(params.domainUpper[a]);
    if (p[a] >= upper)
      p[a] -= float(params.period[a]);
    else if (p[a] < lower)
      p[a] += float(params.period[a]);
    if (p[a] >= upper) p[a] = lower;  // a point just below the lower face rounded onto the upper
  }
  return p;
}

// wrapPeriodic() with the round's parameters, as the kernels do it: the anchor moves.
CellPoint wrap(const shared::TraceParams& params, CellPoint p) {
  if (params.periodicAxes == 0 || !isNear(p)) return p;
  const glm::ivec3 cell = cellOf(p);
  for (int a = 0; a < 3; ++a) {
    if ((params.periodicAxes & (1u << a)) == 0) continue;
    if (cell[a] >= params.domainUpper[a])
      p.anchor[a] -= params.period[a];
    else if (cell[a] < params.domainLower[a])
      p.anchor[a] += params.period[a];
  }
  return p;
}

}  // namespace

shared::LineRound advanceLine(const VectorVolume& volume, const shared::TraceParams& params,
                              shared::LineState& state, const PointEmitter& emit) {
  RegionCache cache;
  // With deep positions the anchor moves (cell_point.hpp); without, it stays zero and offsets
  // are float cell units.
  const bool deep = params.deepPositions != 0;
  const auto sample = [&](const CellPoint& p) {
    return deep ? sampleVector(volume, wrap(params, p), &cache)
                : sampleVector(volume, CellPoint(wrapCellUnits(params, p.offset)), &cache);
  };
  const auto sampleEnd = [&](const CellPoint& p) { return sample(deep ? normalized(p) : p); };
  const float sign = state.direction;
  CellPoint x{state.anchor, state.offset};
  float time = state.time, length = state.arcLength;
  std::uint32_t steps = state.steps, emitted = 0;
  float nextStep = state.stepSize;
  const TraceOptions::Box pauseBox{params.pauseLower, params.pauseUpper};
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
    if (taken > 0 && params.pauseOutside && !pauseBox.contains(x.anchor, x.offset))
      break;  // handed on

    // The last step before --max-time is shortened to end on it: the fixed-step integrators
    // scale their stage vectors, rk45 starts from the shortened step.
    const bool adaptive = params.integrator == AMRSTREAM_INTEGRATOR_RK45;
    float h = adaptive && nextStep > 0.0f ? nextStep : params.stepSize;
    const float advance = parameterStep(params, s, h);
    float scale = sign;
    bool endsOnMaxTime = params.maxTime > 0.0f && std::abs(time) + advance > params.maxTime;
    const float remaining = (params.maxTime - std::abs(time)) / advance;
    if (endsOnMaxTime && adaptive) h *= remaining;
    if (endsOnMaxTime && !adaptive) scale = sign * remaining;

    const auto stage = [&](const VectorSample& at, float step) {
      return scale * direction(params, at, step);
    };
    const StepOutcome step = adaptive
                                 ? dormandPrinceStep(params, x, s, h, sample, sampleEnd, stage)
                                 : fixedStep(params.integrator, x, s, h, sample, sampleEnd, stage);
    if ((reason = step.reason)) break;
    endsOnMaxTime = endsOnMaxTime && step.step == h;
    const CellPoint unwrapped = step.unwrapped;  // the same anchor as x
    const VectorSample sNext = step.next;

    if (params.maxLength > 0.0f) {
      const float stepLength = glm::length(params.spacing * (unwrapped.offset - x.offset));
      if (length + stepLength > params.maxLength) {
        reason = AMRSTREAM_REASON_MAX_LENGTH;
        break;
      }
      length += stepLength;
    }
    time =
        endsOnMaxTime ? sign * params.maxTime : time + sign * parameterStep(params, s, step.step);
    nextStep = step.nextStep;
    x = deep ? normalized(wrap(params, unwrapped))
             : CellPoint(wrapCellUnits(params, unwrapped.offset));
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
  state = {x.offset, time, length, steps, state.line, sign, nextStep, x.anchor};
  return {state.line, emitted, steps, reason};
}

}  // namespace amrstream::flow
