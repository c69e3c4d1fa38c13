// Where an equirectangular environment image (--environment FILE.hdr) is read for a direction, the
// same for the renderer and the reference path tracer: the image's centre column looks along −Z
// (glTF's forward), u grows towards +X, and its top row is +Y. The column at u = 0 and 1 looks
// along +Z, where the image wraps. The image may be turned about +Y (--environment-rotation).
#ifndef VCT_EQUIRECTANGULAR_H
#define VCT_EQUIRECTANGULAR_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

// (u, v) of the unit `direction` in an image turned `turns` of a full turn about +Y, counter-clockwise
// seen from above (a right-handed rotation: a quarter turn brings what the image shows along −Z to
// −X). v is in [0, 1]; u in [0, 2), for a sampler that repeats it.
SHARED_FN vec2 equirectangularCoordinates(vec3 direction, float turns) {
    float u = 0.5f + atan(direction.x, -direction.z) * 0.15915494f + turns;  // 1 / 2π
    float v = acos(clamp(direction.y, -1.0f, 1.0f)) * 0.31830989f;   // 1 / π
    return vec2(u, v);
}

// The unit direction an image turned `turns` shows at (u, v): equirectangularCoordinates inverted.
SHARED_FN vec3 equirectangularDirection(vec2 uv, float turns) {
    float phi = (uv.x - 0.5f - turns) * 6.28318531f;
    float theta = uv.y * 3.14159265f;
    return vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}

// The mip level of a `width`-texel-wide image whose texels span a cone of half-angle tangent
// `tanHalfAperture`: along the equator a texel spans 2π / width radians.
SHARED_FN float equirectangularLevel(float tanHalfAperture, float width) {
    float coneAngle = 2.0f * atan(tanHalfAperture);
    return max(log2(max(coneAngle * width * 0.15915494f, 1e-6f)), 0.0f);
}

VCT_SHARED_END

#endif
