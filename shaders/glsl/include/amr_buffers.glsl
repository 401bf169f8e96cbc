// The buffers every tracing kernel binds (set 0); their structs are in shared/.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "../shared/amr_types.h"
#include "../shared/trace_codes.h"
#include "../shared/trace_params.h"

layout(scalar, set = 0, binding = 0) uniform ParamsBlock { TraceParams params; };
layout(scalar, set = 0, binding = 1) readonly buffer BrickBuffer { Brick bricks[]; };
layout(scalar, set = 0, binding = 2) readonly buffer ValueBuffer { vec3 values[]; };
layout(scalar, set = 0, binding = 3) readonly buffer RegionBuffer { Region regions[]; };
layout(scalar, set = 0, binding = 4) readonly buffer RegionBrickBuffer { uint regionBricks[]; };
layout(scalar, set = 0, binding = 5) readonly buffer SeedBuffer { vec3 seeds[]; };
layout(scalar, set = 0, binding = 6) writeonly buffer PositionBuffer { vec3 positions[]; };
layout(scalar, set = 0, binding = 7) writeonly buffer TimeBuffer { float times[]; };
layout(scalar, set = 0, binding = 8) writeonly buffer VectorBuffer { vec3 vectors[]; };
layout(scalar, set = 0, binding = 9) writeonly buffer PointCountBuffer { uint pointCounts[]; };
layout(scalar, set = 0, binding = 10) writeonly buffer ReasonBuffer { int reasons[]; };
// Binding 11 is the backend's point-location structure (region tree or acceleration structure).
