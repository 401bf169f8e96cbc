// The bindings of the three kernels that compact a tracing round's output (scan_lines.comp,
// scan_blocks.comp, compact_round.comp): an exclusive prefix sum over the lines of (points
// emitted, still running), then every line's points moved to its place in one dense run and the
// running lines' states packed for the next round. Thread order is kept, so the lines of a
// subgroup stay neighbours in space round after round.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "../shared/line_state.h"
#include "../shared/round_bindings.h"
#include "../shared/round_params.h"
#include "../shared/trace_codes.h"

layout(push_constant, scalar) uniform CompactionBlock { CompactionParams pc; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_LINE_ROUNDS)
readonly buffer LineRoundBuffer { LineRound lineRounds[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_PREFIX)
buffer PrefixBuffer { uvec2 prefix[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_BLOCK_SUMS)
buffer BlockSumBuffer { uvec2 blockSums[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_SUMMARY)
buffer SummaryBuffer { RoundSummary summary; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_STATES)
readonly buffer StatesBuffer { LineState states[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_NEXT_STATES)
writeonly buffer NextStatesBuffer { LineState nextStates[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_POSITIONS)
readonly buffer PositionBuffer { vec3 positions[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_TIMES)
readonly buffer TimeBuffer { float times[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_VECTORS)
readonly buffer VectorBuffer { vec3 vectors[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_REGION_IDS)
readonly buffer RegionIdBuffer { int regionIds[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_DENSE_POSITIONS)
writeonly buffer DensePositionBuffer { vec3 densePositions[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_DENSE_TIMES)
writeonly buffer DenseTimeBuffer { float denseTimes[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_DENSE_VECTORS)
writeonly buffer DenseVectorBuffer { vec3 denseVectors[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_COMPACTION_DENSE_REGION_IDS)
writeonly buffer DenseRegionIdBuffer { int denseRegionIds[]; };

const uint kGroup = AMRSTREAM_COMPACTION_GROUP;
shared uvec2 partial[kGroup];

// Inclusive scan of partial[] across the workgroup (Hillis-Steele); every invocation takes part.
void scanPartials() {
  const uint l = gl_LocalInvocationID.x;
  for (uint offset = 1; offset < kGroup; offset <<= 1) {
    barrier();
    const uvec2 add = l >= offset ? partial[l - offset] : uvec2(0);
    barrier();
    partial[l] += add;
  }
  barrier();
}
