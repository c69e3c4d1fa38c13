#version 460
// Reduced diffuse cones, step 2 (reduced_diffuse.glsl): every sample's light from the four
// representatives around it on its own surface, or the sample listed for its own cones.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D diffuse;
layout(std430, set = 0, binding = 2) writeonly buffer Fallback { uint fallbackSamples[]; };
layout(std430, set = 0, binding = 3) buffer FallbackList { WorkListHeader fallback; };
layout(set = 0, binding = 6) uniform sampler2D gPosition;
layout(set = 0, binding = 7) uniform sampler2D gNormal;
layout(set = 0, binding = 8) uniform sampler2D gathered;
layout(push_constant) uniform Push { uint groupLimit; };

#include "reduced_diffuse.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.renderSize)))) return;
    vec4 positionMaterial = texelFetch(gPosition, pixel, 0);
    if (positionMaterial.w < 0.5f) {
        imageStore(diffuse, pixel, vec4(0.0f));  // background: shading reads nothing here
        return;
    }
    vec3 position = positionMaterial.xyz;
    vec3 normal = normalize(texelFetch(gNormal, pixel, 0).xyz);
    float f = float(frame.diffuseDownscale);
    // Representative t sits at t·f + f/2 + ½ in samples: sample `pixel` is at reduced coordinate q.
    vec2 q = (vec2(pixel) - 0.5f * f) / f;
    ivec2 base = ivec2(floor(q));
    vec2 fraction = q - vec2(base);
    ivec2 last = textureSize(gathered, 0) - 1;
    float voxelSize = frame.grid.originVoxelSize.w;
    vec4 sum = vec4(0.0f);
    float weightSum = 0.0f;
    for (int i = 0; i < 4; ++i) {
        ivec2 offset = ivec2(i & 1, i >> 1);
        ivec2 texel = clamp(base + offset, ivec2(0), last);
        ivec2 source = representativeSample(texel);
        vec4 sourcePosition = texelFetch(gPosition, source, 0);
        if (sourcePosition.w < 0.5f) continue;  // background: nothing was gathered
        vec3 sourceNormal = normalize(texelFetch(gNormal, source, 0).xyz);
        float planeDistance = abs(dot(normal, sourcePosition.xyz - position)) / voxelSize;
        if (planeDistance > UPSAMPLE_PLANE_TOLERANCE) continue;
        vec2 bilinear = mix(1.0f - fraction, fraction, vec2(offset));
        float weight = bilinear.x * bilinear.y * pow(max(dot(normal, sourceNormal), 0.0f), UPSAMPLE_NORMAL_POWER);
        sum += weight * texelFetch(gathered, texel, 0);
        weightSum += weight;
    }
    if (weightSum > UPSAMPLE_MIN_WEIGHT) {
        imageStore(diffuse, pixel, sum / weightSum);
        return;
    }
    uint slot = atomicAdd(fallback.count, 1u);
    fallbackSamples[slot] = packSample(pixel);
    if (startsWorkgroup(slot, groupLimit)) atomicAdd(fallback.groupsX, 1u);
}
