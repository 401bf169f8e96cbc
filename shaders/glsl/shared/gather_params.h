// The copy of scattered runs of words into one buffer (gather_runs.comp): one region per run;
// short runs are copied one invocation per word, long runs one workgroup per run. Scalar layout,
// shared with the host.
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
  uint firstWord;  // the words of the dispatch's regions before this one
};

struct GatherParams {
  uint firstRegion;  // the dispatch's regions: [firstRegion, firstRegion + regionCount)
  uint regionCount;
  // Per word: the word invocation 0 copies, counted over the dispatch's regions, and the words
  // of them all. Per run (words 0): workgroup i copies region firstRegion + i.
  uint firstWord;
  uint words;
};

#define AMRSTREAM_GATHER_GROUP 64

#ifdef __cplusplus
static_assert(sizeof(GatherRegion) == 16 && sizeof(GatherParams) == 16);
}  // namespace amrstream::shared
#endif

#endif
