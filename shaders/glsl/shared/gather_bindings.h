// The descriptor bindings of gather_runs.comp (set 0), shared with the host that writes them
// (src/gpu/device_traces.cpp).
#ifndef AMRSTREAM_SHARED_GATHER_BINDINGS_H
#define AMRSTREAM_SHARED_GATHER_BINDINGS_H

#define AMRSTREAM_BINDING_GATHER_SOURCE 0
#define AMRSTREAM_BINDING_GATHER_TARGET 1
#define AMRSTREAM_BINDING_GATHER_REGIONS 2  // GatherRegion
#define AMRSTREAM_GATHER_BINDING_COUNT 3

#endif
