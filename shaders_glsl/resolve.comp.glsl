#version 460
// Each output pixel is the average of its supersampled square: a box filter over factor × factor
// samples, so a pixel means the mean radiance over its area, as the path tracer computes it. With
// still frames to average (ShadingSettings::diffuseConeTurns), the output keeps their running mean:
// the frame's share is `weight` (1 / frames averaged so far; 1 replaces what was there).
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = SUPERSAMPLED_BINDING) uniform sampler2D supersampled;
layout(set = 0, binding = RESOLVED_BINDING, rgba32f) uniform image2D resolved;
layout(push_constant) uniform Push {
    uint factor;
    float weight;
};

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(resolved)))) return;
    vec3 sum = vec3(0.0f);
    for (uint y = 0u; y < factor; ++y)
        for (uint x = 0u; x < factor; ++x)
            sum += texelFetch(supersampled, pixel * int(factor) + ivec2(x, y), 0).rgb;
    vec3 frameMean = sum / float(factor * factor);
    // Not mix() at weight 1: what was there is undefined then (a NaN would stay).
    if (weight < 1.0f) frameMean = mix(imageLoad(resolved, pixel).rgb, frameMean, weight);
    imageStore(resolved, pixel, vec4(frameMean, 1.0f));
}
