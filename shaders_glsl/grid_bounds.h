// The viewer's voxel-grid box (src/view/present_pass.cpp): what its line shaders are pushed.
#ifndef VCT_GRID_BOUNDS_H
#define VCT_GRID_BOUNDS_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

struct GridBoundsPush {
    mat4 viewProjection;  // the renderer's frame (world − scene origin) to clip space
    vec4 boxMin;          // xyz: the grid's min corner, in that frame
    vec4 boxMax;          // xyz: its max corner
    vec4 color;           // written as it is (the swapchain holds sRGB-encoded values)
};

VCT_SHARED_END

#endif
