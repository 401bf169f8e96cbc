// The buffers every tracing-round kernel binds (set 0); their structs are in shared/. A round
// advances line t of the dispatch from statesIn[t] to statesOut[t], reports it in lineRounds[t]
// and writes its k-th emitted point to slot k * params.lineCount + t of the output arrays.
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
#include "../shared/trace_params.h"

layout(scalar, set = 0, binding = 0) uniform ParamsBlock { TraceParams params; };
layout(scalar, set = 0, binding = 1) readonly buffer BrickBuffer { Brick bricks[]; };
// The vector's values padded to 16 bytes (VolumeBuffers::values): one aligned load per cell.
layout(std430, set = 0, binding = 2) readonly buffer ValueBuffer { vec4 values[]; };
layout(scalar, set = 0, binding = 3) readonly buffer RegionBuffer { Region regions[]; };
// The regions' brick lists with each brick's record in place (VolumeBuffers::regionBricks), so
// that a sample reads a brick in one load rather than its index and then the record.
layout(scalar, set = 0, binding = 4) readonly buffer RegionBrickBuffer {
  Brick regionBrickRecords[];
};
#ifdef AMRSTREAM_PROBE_POINTS  // the probe (locate_probe.glsl): binding 5 holds bare points
layout(scalar, set = 0, binding = 5) readonly buffer ProbePointBuffer { vec3 probePoints[]; };
#else
layout(scalar, set = 0, binding = 5) readonly buffer StatesInBuffer { LineState statesIn[]; };
#endif
layout(scalar, set = 0, binding = 6) writeonly buffer StatesOutBuffer { LineState statesOut[]; };
layout(scalar, set = 0, binding = 7) writeonly buffer LineRoundBuffer { LineRound lineRounds[]; };
layout(scalar, set = 0, binding = 8) writeonly buffer PositionBuffer { vec3 outPositions[]; };
layout(scalar, set = 0, binding = 9) writeonly buffer TimeBuffer { float outTimes[]; };
layout(scalar, set = 0, binding = 10) writeonly buffer VectorBuffer { vec3 outVectors[]; };
layout(scalar, set = 0, binding = 11) writeonly buffer RegionIdBuffer { int outRegions[]; };
#ifdef AMRSTREAM_DUAL_ADDRESS
// The dual cells (VolumeBuffers::dualValues) read through params.dualValuesAddress rather than a
// binding, so that they may exceed maxStorageBufferRange: one 128-byte block per dual cell.
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer DualCellBlock {
  vec4 corners[8];
};
#endif
// Binding 12 is the backend's point-location structure (region tree or acceleration structure).
#define AMRSTREAM_LOCATE_BINDING 12
// The linear interpolant's cells: per value slot 48 bytes, the value, then the gradients of its
// three components (unread with the tent interpolant). The compute kernel reads them as three
// 16-byte words, which std430 keeps aligned, so a cell is three wide loads (1.3x on an H100 at
// 2^20 particles); the ray tracing pipeline ran 1.5x slower so, and it and the ray query kernel
// (unmeasured on hardware) read four vec3.
#ifdef AMRSTREAM_LINEAR_CELL_WORDS
layout(std430, set = 0, binding = 13) readonly buffer LinearCellBuffer { vec4 linearCellWords[]; };
#else
layout(scalar, set = 0, binding = 13) readonly buffer LinearCellBuffer { vec3 linearCells[]; };
#endif
