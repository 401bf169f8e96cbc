// The descriptor bindings of build_dual_cells.comp (set 0), shared with the host that writes them
// (src/gpu/dual_cells.cpp).
#ifndef AMRSTREAM_SHARED_DUAL_CELL_BINDINGS_H
#define AMRSTREAM_SHARED_DUAL_CELL_BINDINGS_H

#define AMRSTREAM_BINDING_DUAL_CELL_BRICKS 0
#define AMRSTREAM_BINDING_DUAL_CELL_VALUES 1
#define AMRSTREAM_BINDING_DUAL_CELL_OFFSETS 2  // each brick's first dual cell
#define AMRSTREAM_DUAL_CELL_BINDING_COUNT 3

#endif
