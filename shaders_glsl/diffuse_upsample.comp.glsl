#version 460
// Reduced diffuse cones, step 3 (reduced_diffuse.glsl): every sample's light from the four
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
layout(set = 0, binding = 9) uniform sampler2D representatives;
layout(set = 0, binding = 10) uniform sampler2D representativeNormals;
layout(set = 0, binding = 12) uniform sampler2D lastDiffuse;
layout(set = 0, binding = 13) uniform sampler2D lastPosition;  // the last frame's G-buffer
layout(set = 0, binding = 14) uniform sampler2D lastNormal;
layout(push_constant) uniform Push {
    mat4 lastViewProjection;
    uint groupLimit;
    uint refreshPhase;
    uint haveHistory;  // 0: every sample that cannot be upsampled traces
};

#include "reduced_diffuse.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.renderSize)))) return;
    vec4 positionMaterial = texelFetch(gPosition, pixel, 0);
    if (positionMaterial.w < 0.5f) {
        imageStore(diffuse, pixel, vec4(0.0f));  // background: shading reads nothing here
        return;
    }
    vec3 normal = normalize(texelFetch(gNormal, pixel, 0).xyz);
    SurfaceBlend blend = blendOnSurface(gathered, representatives, representativeNormals,
                                        reducedCoordinate(vec2(pixel)), positionMaterial.xyz, normal);
    if (blend.weight > UPSAMPLE_MIN_WEIGHT) {
        imageStore(diffuse, pixel, blend.sum / blend.weight);
        return;
    }
    vec4 light;
    if (haveHistory != 0u && !refreshes(pixel, refreshPhase) &&
        lastLight(lastViewProjection, lastDiffuse, lastPosition, lastNormal, false, positionMaterial.xyz, normal,
                  light)) {
        imageStore(diffuse, pixel, light);
        return;
    }
    uint slot = atomicAdd(fallback.count, 1u);
    fallbackSamples[slot] = packSample(pixel);
    if (startsWorkgroup(slot, groupLimit)) atomicAdd(fallback.groupsX, 1u);
}
