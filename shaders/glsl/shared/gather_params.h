// The copy of scattered runs of words into one buffer (gather_runs.comp): one region per run,
// one workgroup per region. Scalar layout, shared with the host.
#ifndef AMRSTREAM_SHARED_GATHER_PARAMS_H
#define AMRSTREAM_SHARED_GATHER_PARAMS_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

struct GatherRegion {
  uint source;  // first word in the source buffer
  uint target;  // first word in the target buffer
  uint words;
  uint pad;
};

struct GatherParams {
  uint firstRegion;  // the dispatch's workgroup i copies region firstRegion + i
};

#define AMRSTREAM_GATHER_GROUP 64

#ifdef __cplusplus
static_assert(sizeof(GatherRegion) == 16 && sizeof(GatherParams) == 4);
}  // namespace amrstream::shared
#endif

#endif
