// The sky's radiance by direction, as every ray that leaves the scene sees it (cones leaving the
// grid, the camera's view past the scene): frame.environment.rgb, times the environment image
// where one is bound (frame.environment.w = 1), read through its mip chain blurred over the cone's
// aperture, turned as --environment-rotation says. Without an image, a 1 × 1 white one is bound.
// The binding is the same in every pass.
#ifndef VCT_SKY_GLSL
#define VCT_SKY_GLSL

#include "bindings.h"
#include "equirectangular.h"

layout(set = 0, binding = SKY_BINDING) uniform sampler2D environmentMap;

vec3 skyRadiance(vec3 direction, float tanHalfAperture) {
    if (frame.environment.w < 0.5f) return frame.environment.rgb;
    float level = equirectangularLevel(tanHalfAperture, float(textureSize(environmentMap, 0).x));
    vec2 uv = equirectangularCoordinates(direction, frame.environmentTurns);
    return frame.environment.rgb * textureLod(environmentMap, uv, level).rgb;
}

#endif
