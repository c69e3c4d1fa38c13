#version 460
// Reduced diffuse cones, step 1 (reduced_diffuse.glsl): each reduced texel's representative, and
// its light from the last frame where that holds; the others are listed to trace.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = REDUCED_LIGHT_BINDING, rgba32f) uniform writeonly image2D gathered;
layout(std430, set = 0, binding = TRACED_SAMPLES_BINDING) writeonly buffer Traced { uint tracedSamples[]; };
layout(std430, set = 0, binding = TRACED_LIST_BINDING) buffer TracedList { WorkListHeader traced; };
layout(set = 0, binding = REDUCED_POSITIONS_BINDING, rgba32f) uniform writeonly image2D representatives;
layout(set = 0, binding = REDUCED_NORMALS_BINDING, rgba32f) uniform writeonly image2D representativeNormals;
layout(set = 0, binding = G_POSITION_BINDING) uniform sampler2D gPosition;
layout(set = 0, binding = G_NORMAL_BINDING) uniform sampler2D gNormal;
layout(set = 0, binding = LAST_REDUCED_LIGHT_BINDING) uniform sampler2D lastGathered;
layout(set = 0, binding = LAST_REDUCED_POSITIONS_BINDING) uniform sampler2D lastRepresentatives;
layout(set = 0, binding = LAST_REDUCED_NORMALS_BINDING) uniform sampler2D lastRepresentativeNormals;
layout(push_constant) uniform Push {
    mat4 lastViewProjection;
    uint groupLimit;
    uint refreshPhase;
    uint haveHistory;  // 0: every texel traces
};

#include "reduced_diffuse.glsl"

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(gathered)))) return;
    ivec2 source = representativeSample(texel);
    vec4 positionMaterial = texelFetch(gPosition, source, 0);
    if (positionMaterial.w < 0.5f) {
        imageStore(gathered, texel, vec4(0.0f));
        imageStore(representatives, texel, vec4(0.0f));
        return;
    }
    vec3 position = positionMaterial.xyz;
    vec3 normal = normalize(texelFetch(gNormal, source, 0).xyz);
    imageStore(representatives, texel, vec4(position, 1.0f));
    imageStore(representativeNormals, texel, vec4(normal, 0.0f));
    vec4 light;
    if (haveHistory != 0u && !refreshes(texel, refreshPhase) &&
        lastLight(lastViewProjection, lastGathered, lastRepresentatives, lastRepresentativeNormals, true, position,
                  normal, light)) {
        imageStore(gathered, texel, light);
        return;
    }
    uint slot = atomicAdd(traced.count, 1u);
    tracedSamples[slot] = packSample(source);
    if (startsWorkgroup(slot, groupLimit)) atomicAdd(traced.groupsX, 1u);
}
