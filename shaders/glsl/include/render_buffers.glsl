// The buffers every rendering kernel binds (set 0); their structs are in shared/, their bindings
// in shared/render_bindings.h. AMRSTREAM_BINDING_RENDER_TUBES is the backend's tube structure
// (include/tubes_*.glsl).
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "../shared/amr_types.h"
#include "cell_point.glsl"
#include "../shared/render_bindings.h"
#include "../shared/render_types.h"

layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_PARAMS)
uniform RenderParamsBlock { RenderParams params; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_BRICKS)
readonly buffer BrickBuffer { Brick bricks[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_SCALARS)
readonly buffer ScalarBuffer { float scalars[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_REGIONS)
readonly buffer RegionBuffer { Region regions[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_REGION_BRICKS)
readonly buffer RegionBrickBuffer { uint regionBricks[]; };
#define AMRSTREAM_TREE_BINDING AMRSTREAM_BINDING_RENDER_REGION_TREE
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_SEGMENTS)
readonly buffer SegmentBuffer { TubeSegment segments[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_COLOUR_MAP)
readonly buffer ColourMapBuffer { vec3 colourMap[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_ACCUMULATION)
buffer AccumulationBuffer { vec4 accumulation[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_PIXELS)
writeonly buffer PixelBuffer { uint pixels[]; };
// The context scalar's gradient per value slot, per finest cell (the linear interpolant; one
// element, unread, with the tent).
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_SCALAR_GRADIENTS)
readonly buffer ScalarGradientBuffer { vec3 scalarGradients[]; };
