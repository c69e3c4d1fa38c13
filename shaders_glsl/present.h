// What the viewer's present pass (src/view/present_pass.cpp) pushes to its shaders: the tone map
// and the voxel grid's box.
#ifndef VCT_PRESENT_H
#define VCT_PRESENT_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

struct TonemapPush {
    vec2 areaOffset;       // the image's top-left corner in the window, pixels
    vec2 inverseAreaSize;  // 1 / its size
    float exposure;
    uint applyToneCurve;  // 0 = show values as they are (clamped to 0..1)
    uint toneCurve;       // TONE_CURVE_* (tone_curve.h)
};

struct GridBoundsPush {
    mat4 viewProjection;  // the renderer's frame (world − scene origin) to clip space
    vec4 boxMin;          // xyz: the grid's min corner, in that frame
    vec4 boxMax;          // xyz: its max corner
    vec4 color;           // written as it is (the swapchain holds sRGB-encoded values)
};

VCT_SHARED_END

#endif
