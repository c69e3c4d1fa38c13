#version 460
// Reduced diffuse cones, step 3b (reduced_diffuse.glsl): each sample that step 3 could not
// upsample takes its own light of the last frame, where the last frame saw its surface and it does
// not refresh this frame, or is listed to trace its own cones (step 4).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = WORK_LIST_GROUP_SIZE) in;

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = DIFFUSE_SAMPLES_BINDING, rgba32f) uniform writeonly image2D diffuse;
layout(std430, set = 0, binding = FALLBACK_SAMPLES_BINDING) writeonly buffer Fallback { uint fallbackSamples[]; };
layout(std430, set = 0, binding = FALLBACK_LIST_BINDING) buffer FallbackList { WorkListHeader fallback; };
layout(std430, set = 0, binding = EDGE_SAMPLES_BINDING) readonly buffer Edge { uint edgeSamples[]; };
layout(std430, set = 0, binding = EDGE_LIST_BINDING) readonly buffer EdgeList { WorkListHeader edge; };
layout(set = 0, binding = G_POSITION_BINDING) uniform sampler2D gPosition;
layout(set = 0, binding = G_NORMAL_BINDING) uniform sampler2D gNormal;
layout(set = 0, binding = LAST_DIFFUSE_SAMPLES_BINDING) uniform sampler2D lastDiffuse;
layout(set = 0, binding = LAST_G_POSITION_BINDING) uniform sampler2D lastPosition;  // the last frame's G-buffer
layout(set = 0, binding = LAST_G_NORMAL_BINDING) uniform sampler2D lastNormal;
layout(push_constant) uniform Push {
    mat4 lastViewProjection;
    uint groupLimit;
    uint refreshPhase;
    uint haveHistory;  // 0: every sample listed here traces
};

#include "reduced_diffuse.glsl"

void historyOrTrace(ivec2 pixel) {
    vec3 position = texelFetch(gPosition, pixel, 0).xyz;
    vec3 normal = normalize(texelFetch(gNormal, pixel, 0).xyz);
    vec4 light;
    if (haveHistory != 0u && !refreshes(pixel, refreshPhase) &&
        lastLight(lastViewProjection, lastDiffuse, lastPosition, lastNormal, false, position, normal, light)) {
        imageStore(diffuse, pixel, light);
        return;
    }
    uint slot = atomicAdd(fallback.count, 1u);
    fallbackSamples[slot] = packSample(pixel);
    if (startsWorkgroup(slot, groupLimit)) atomicAdd(fallback.groupsX, 1u);
}

void main() {
    // The dispatch may be capped below ⌈count / group size⌉: each invocation strides over the rest.
    uint stride = gl_NumWorkGroups.x * WORK_LIST_GROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < edge.count; i += stride) historyOrTrace(unpackSample(edgeSamples[i]));
}
