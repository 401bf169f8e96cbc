// The descriptor bindings of the tracing-round kernels and the point-location probe (set 0,
// include/amr_buffers.glsl), shared with the host that writes them (src/gpu/gpu_rounds.cpp,
// src/gpu/vector_probe.cpp).
#ifndef AMRSTREAM_SHARED_TRACE_BINDINGS_H
#define AMRSTREAM_SHARED_TRACE_BINDINGS_H

#define AMRSTREAM_BINDING_TRACE_PARAMS 0  // the uniform TraceParams
#define AMRSTREAM_BINDING_TRACE_BRICKS 1
#define AMRSTREAM_BINDING_TRACE_VALUES 2
#define AMRSTREAM_BINDING_TRACE_REGIONS 3
#define AMRSTREAM_BINDING_TRACE_REGION_BRICKS 4
#define AMRSTREAM_BINDING_TRACE_STATES_IN 5
// The probe (include/locate_probe.glsl) reads its points in the line states' place.
#define AMRSTREAM_BINDING_TRACE_PROBE_POINTS AMRSTREAM_BINDING_TRACE_STATES_IN
#define AMRSTREAM_BINDING_TRACE_STATES_OUT 6
#define AMRSTREAM_BINDING_TRACE_LINE_ROUNDS 7
#define AMRSTREAM_BINDING_TRACE_POSITIONS 8
#define AMRSTREAM_BINDING_TRACE_TIMES 9
#define AMRSTREAM_BINDING_TRACE_VECTORS 10
#define AMRSTREAM_BINDING_TRACE_REGION_IDS 11
// The backend's point-location structure: the region tree, or an acceleration structure.
#define AMRSTREAM_BINDING_TRACE_LOCATE 12
#define AMRSTREAM_BINDING_TRACE_LINEAR_CELLS 13
#define AMRSTREAM_TRACE_BINDING_COUNT 14

#endif
