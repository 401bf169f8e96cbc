// The layout of the vector's dual cells on the device (build_dual_cells.comp,
// VolumeBuffers::dualValues). Scalar layout, shared with the host.
#ifndef AMRSTREAM_SHARED_DUAL_CELL_PARAMS_H
#define AMRSTREAM_SHARED_DUAL_CELL_PARAMS_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

struct DualCellParams {
  uvec2 dualValuesAddress;  // where dual cell d's 128 bytes start at + 128 d (low word first)
  uint firstBrick;          // the dispatch's workgroup i fills brick firstBrick + i
};

#define AMRSTREAM_DUAL_CELL_GROUP 64

#ifdef __cplusplus
static_assert(sizeof(DualCellParams) == 12);
}  // namespace amrstream::shared
#endif

#endif
