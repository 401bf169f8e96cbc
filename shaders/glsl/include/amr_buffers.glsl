// The buffers every tracing-round kernel binds (set 0); their structs are in shared/, their
// bindings in shared/trace_bindings.h. A round advances line t of the dispatch from statesIn[t]
// to statesOut[t], reports it in lineRounds[t] and writes its k-th emitted point to slot
// k * params.lineCount + t of the output arrays.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#ifdef AMRSTREAM_DUAL_ADDRESS
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
#endif

#include "../shared/amr_types.h"
#include "cell_point.glsl"
#include "../shared/line_state.h"
#include "../shared/trace_codes.h"
#include "../shared/trace_bindings.h"
#include "../shared/trace_params.h"

layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_PARAMS)
uniform ParamsBlock { TraceParams params; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_BRICKS)
readonly buffer BrickBuffer { Brick bricks[]; };
// The vector's values padded to 16 bytes (VolumeBuffers::values): one aligned load per cell.
layout(std430, set = 0, binding = AMRSTREAM_BINDING_TRACE_VALUES)
readonly buffer ValueBuffer { vec4 values[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_REGIONS)
readonly buffer RegionBuffer { Region regions[]; };
// The regions' brick lists with each brick's record in place (VolumeBuffers::regionBricks), so
// that a sample reads a brick in one load rather than its index and then the record.
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_REGION_BRICKS)
readonly buffer RegionBrickBuffer { Brick regionBrickRecords[]; };
#if defined(AMRSTREAM_PROBE_POINTS)  // the probe (locate_probe.glsl): bare points for states
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_PROBE_POINTS)
readonly buffer ProbePointBuffer { vec3 probePoints[]; };
#elif defined(AMRSTREAM_PROBE_GRID)  // the grid probe: the grid of points for states
#include "../shared/plane_lic.h"
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_PROBE_POINTS)
readonly buffer ProbeGridBuffer { ProbeGrid probeGrid; };
#else
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_STATES_IN)
readonly buffer StatesInBuffer { LineState statesIn[]; };
#endif
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_STATES_OUT)
writeonly buffer StatesOutBuffer { LineState statesOut[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_LINE_ROUNDS)
writeonly buffer LineRoundBuffer { LineRound lineRounds[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_POSITIONS)
writeonly buffer PositionBuffer { vec3 outPositions[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_TIMES)
writeonly buffer TimeBuffer { float outTimes[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_VECTORS)
writeonly buffer VectorBuffer { vec3 outVectors[]; };
#ifdef AMRSTREAM_PROBE_POINTS  // the probe reads each point's region hint there first
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_REGION_IDS)
buffer RegionIdBuffer { int outRegions[]; };
#else
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_REGION_IDS)
writeonly buffer RegionIdBuffer { int outRegions[]; };
#endif
#ifdef AMRSTREAM_DUAL_ADDRESS
// The dual cells (VolumeBuffers::dualValues) read through params.dualValuesAddress rather than a
// binding, so that they may exceed maxStorageBufferRange: one 128-byte block per dual cell.
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer DualCellBlock {
  vec4 corners[8];
};
#endif
// The backend's locate_*.glsl declares its point-location structure at
// AMRSTREAM_BINDING_TRACE_LOCATE.
// The linear interpolant's cells: per value slot 48 bytes, the value, then the gradients of its
// three components (unread with the tent interpolant). The compute kernel reads them as three
// 16-byte words, which std430 keeps aligned, so a cell is three wide loads; the ray tracing
// pipeline and the ray query kernel read four vec3, which is faster for the pipeline
// (docs/performance-notes.md, "One 48-byte record per linear cell, read as three words").
#ifdef AMRSTREAM_LINEAR_CELL_WORDS
layout(std430, set = 0, binding = AMRSTREAM_BINDING_TRACE_LINEAR_CELLS)
readonly buffer LinearCellBuffer { vec4 linearCellWords[]; };
#else
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_TRACE_LINEAR_CELLS)
readonly buffer LinearCellBuffer { vec3 linearCells[]; };
#endif
