// The buffers every rendering kernel binds (set 0); their structs are in shared/. Binding 10 is
// the backend's tube structure (include/tubes_*.glsl).
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "../shared/amr_types.h"
#include "cell_point.glsl"
#include "../shared/render_types.h"

layout(scalar, set = 0, binding = 0) uniform RenderParamsBlock { RenderParams params; };
layout(scalar, set = 0, binding = 1) readonly buffer BrickBuffer { Brick bricks[]; };
layout(scalar, set = 0, binding = 2) readonly buffer ScalarBuffer { float scalars[]; };
layout(scalar, set = 0, binding = 3) readonly buffer RegionBuffer { Region regions[]; };
layout(scalar, set = 0, binding = 4) readonly buffer RegionBrickBuffer { uint regionBricks[]; };
#define AMRSTREAM_TREE_BINDING 5
layout(scalar, set = 0, binding = 6) readonly buffer SegmentBuffer { TubeSegment segments[]; };
layout(scalar, set = 0, binding = 7) readonly buffer ColourMapBuffer { vec3 colourMap[]; };
layout(scalar, set = 0, binding = 8) buffer AccumulationBuffer { vec4 accumulation[]; };
layout(scalar, set = 0, binding = 9) writeonly buffer PixelBuffer { uint pixels[]; };
// The context scalar's gradient per value slot, per finest cell (the linear interpolant; one
// element, unread, with the tent).
layout(scalar, set = 0, binding = 11) readonly buffer ScalarGradientBuffer { vec3 scalarGradients[]; };
